// The roller's steady creep law at one cam angle (docs/cam-follower.md §7): the contact of that angle
// (lib/normal/normal.h on the roller's and the track's profiles, its strips on a grid, with the Heathcote
// offsets of the crowned roller, docs/physics.md §2.4) and the project's steady tangential model on it with the
// longitudinal creepage xi alone: the default model (contact::kDefaultTangentialScheme, the relaxed model of
// lib/tangential/relaxed.h, matched to the exact theory, with the worn contacts' shape factor and strip weights of
// lib/tangential/relaxed_shape.h), the simplified theory (lib/tangential/steady.h, consistent scheme) or Kalker's
// exact theory (lib/tangential/exact.h), as CreepLawSettings::scheme says (the case's cam.tangential.scheme); the
// contact by the normal solver CreepLawSettings::normal asks for (cam.normal.solver). The contact's
// x runs along the pitch tangent t of cam/kinematics.h, so the solver's Fx is the cam's F_t on the roller and
// its xi the cam's (docs/physics.md §1: xi = w_x/V, w_x = R_r (omega_r - omega_r,kin) the roller's slip
// velocity over the cam, xi > 0 a roller lagging the cam, Fx = -G a b C11 xi in the linear range: the consistent
// scheme's to the strip sum's quadrature, the relaxed model's to its creepage factor g_x(a/b, e), 0.97-0.98 at its
// lowest level e = 0.05, held below it). The law is nonlinear and saturating towards -mu F_n sign(xi), one law
// for the roller's dynamics (cam/roller_dynamics.h) and the dissipation (cam/revolution_dissipation.h), so
// that they agree.
#pragma once

#include "cam/kinematics.h"
#include "cam/roller_contact.h"
#include "lib/grid.h"
#include "lib/normal/normal.h"
#include "lib/tangential/tangential.h"

namespace cam {

struct CreepLawSettings {
  contact::GridSpec grid{40, 40};  // the contact's strips (ny across); along x the pure-xi strip is exact
  bool heathcote_slip = true;      // the crowned roller's rolling radius varying across the contact
  // a worn (semi-Hertzian) contact's strips over this fixed lateral extent (profiles' y) instead of the
  // contact's: both 0 = the contact's (lib/normal/semi_hertz.h). The life sets it (cam/cam_life.h).
  double fixed_grid_y_lo_m = 0, fixed_grid_y_hi_m = 0;
  // the semi-Hertzian search's first approach (SemiHertzOptions::initial_approach_m): 0 = its own estimate;
  // cam/worn_revolution.h passes an angle's approach at the life's last evaluation
  double initial_approach_m = 0;
  // with it, d ln F / d ln delta there (SemiHertzOptions::initial_slope; the last solve's approach_slope): 0 = 3/2
  double initial_slope = 0;
  // worn profiles: never Hertz's closed form (NormalProblem::worn), even where a worn profile still fits a
  // constant curvature: the switch between the two would be a jump of the life's rate (they agree to 2e-3)
  bool worn = false;
  // the semi-Hertzian search's load tolerance (SemiHertzOptions::load_rtol)
  double normal_load_rtol = contact::SemiHertzOptions{}.load_rtol;
  // the steady tangential model: Relaxed (the default), Consistent or Exact (Kalker's exact theory on the patch's
  // grid, lib/tangential/exact.h); angle_contact refuses the others
  contact::TangentialScheme scheme = contact::kDefaultTangentialScheme;
  // the normal problem (cam.normal.solver): Auto (Hertz's closed form on the unworn profiles, semi-Hertz on worn
  // ones), SemiHertz, or Halfspace (cam/halfspace_contact.h: the exact normal problem on the angle's fixed lattice,
  // grid.nx cells over the unworn contact's length; over the fixed lateral window above, grid.ny strips there)
  contact::NormalChoice normal = contact::NormalChoice::Auto;
};

// The law the roller's motion (cam/roller_dynamics.h) is solved with for a case whose law is s: on the unworn
// profiles, so the normal problem is Hertz's closed form (auto: the half-space reproduces it to its grid's error,
// docs/halfspace.md), and the exact theory's place taken by the relaxed model matched to it (the motion needs
// some 10^4 steady solves; on the shipped case the roller rolls at every angle, so its F_t is what rolling needs
// whatever the law, docs/cam-follower.md §16). The relaxed and consistent models are their own.
CreepLawSettings motion_law(const CreepLawSettings& s);
// s is its own motion's law: the revolution's rows may take the motion's creepage as it is; otherwise each row's
// creepage is the one whose steady force is the motion's F_t on the row's contact (creepage_for_force)
bool is_motion_law(const CreepLawSettings& s);

struct AngleContact {
  contact::NormalSolution normal;      // the contact, its strips on the grid
  contact::TangentialProblem problem;  // Kalker's coefficients and flexibilities, mu; xi and V set per call
  double G_Pa = 0;                     // the combined shear modulus
  // per strip, the roller's surface below its rolling radius at the reference line, z1(y_j) - z1(y0): strip j's
  // force acts on the roller at the radius R_r minus this (with Heathcote slip; empty without it)
  Eigen::ArrayXd roller_depth_m;
  // likewise the track's surface below the cam's at the reference line, z2(y_j) - z2(y0) (a crowned track)
  Eigen::ArrayXd track_depth_m;
  // the steady model (CreepLawSettings::scheme) and the materials it needs (the relaxed model's levels)
  contact::TangentialScheme scheme = contact::kDefaultTangentialScheme;
  contact::ElasticPair pair;
};

// the cam's tangential models: Relaxed, Consistent and Exact (std::invalid_argument naming them otherwise)
void check_cam_scheme(contact::TangentialScheme scheme);

// the creep force on the roller along t and its torque's correction for the strips' radii:
//   torque about the axle = R_r force - depth_moment,  depth_moment = sum_j F_j (z1(y_j) - z1(y0)) dy
struct CreepForce {
  double force_N = 0;
  double depth_moment_N_m = 0;
  double track_depth_moment_N_m = 0;  // sum_j F_j (z2(y_j) - z2(y0)) dy: the same on the cam's side
};
CreepForce creep_force(const AngleContact& c, double xi);

// z_k(y_j) - z_k(y0) for the strips of a contact (profiles' y = y0 + grid y), k = 1 the roller, 2 the track
Eigen::ArrayXd roller_depth_m(const contact::Profiles& profiles, double y0_m, const contact::Grid& grid);
Eigen::ArrayXd track_depth_m(const contact::Profiles& profiles, double y0_m, const contact::Grid& grid);

// the contact at angle k under normal_load_N (> 0). Throws contact::NormalSolveError when the normal solve
// does not converge, std::invalid_argument for bad values
AngleContact angle_contact(const RollerAndTrack& bodies, const contact::Profiles& profiles, double roller_radius_m,
                           const CamKinematics& k, double normal_load_N, double mu, const CreepLawSettings& s);

// the steady solution at creepage xi and rolling speed V (strips and totals; the fields on the patch's grid only with
// `fields`, e.g. the power density of the flash temperature, cam/cam_lubrication.h) with the contact's model
contact::TangentialSolution steady_creep(const AngleContact& c, double xi, double speed_m_per_s, bool fields = false);

// F_t(xi): the steady creep force on the roller along t (N), independent of V
double steady_creep_force_N(const AngleContact& c, double xi);

// the creep law inverted: the xi whose steady force is force_N, to kCreepForceRtol mu F_n. found = false
// when |force_N| is beyond what the law reaches below |xi| = kMaxCreepage (the roller cannot roll with it)
struct CreepageForForce {
  double xi = 0;
  bool found = false;
  int evaluations = 0;
};
CreepageForForce creepage_for_force(const AngleContact& c, double force_N);
// the same from xi_guess (e.g. the creepage of the same angle on a slightly different contact): a step of the
// linear law's slope from it, the root in the bracket the two make (else a bracket grown around the step's
// end): the same root to the same tolerance, in fewer steady solves
CreepageForForce creepage_for_force(const AngleContact& c, double force_N, double xi_guess);

// the inversion's tolerance on the force: a fraction of the saturated force mu F_n (the steady strip is
// exact to rounding, so the root finder, not the law, sets it)
constexpr double kCreepForceRtol = 1e-10;
// the exact theory's: its solve is iterative (fixed-point residual 1e-9, lib/tangential/exact.h), its force
// known to some 1e-9 of mu F_n, and each dear: the inversion stops at this (on the shipped cam, F_t is 1-2 % of
// mu F_n: the force to 1e-4 of itself)
constexpr double kExactCreepForceRtol = 1e-6;
// the inversion's tolerance on the force for the contact's model (N)
double creep_force_tolerance_N(const AngleContact& c);
// the largest |xi| the inversion searches: a gross slide (the roller's surface at a third of the cam's)
constexpr double kMaxCreepage = 1.0;

}  // namespace cam
