// The relaxed model (solver.tangential: relaxed): Kalker's simplified theory (the steady solver,
// lib/tangential/steady.h, consistent scheme) wrapped so that it reproduces Kalker's exact theory
// (lib/tangential/exact.h) where the bed of springs does not (docs/accuracy-vs-exact.md):
//   - transient: the exact theory's start-up is a relaxation over about 2.7a (the half-space couples
//     the whole contact; the springs only the material that entered it, so they build up over 2a).
//     The model carries effective creepages that relax towards the imposed ones over the rolled
//     distance q,  d c_eff/dq = (c - c_eff) / sigma,  per creepage (xi, eta, phi)
//       sigma_k = s_k(a/b) a (1 - min(e_eff, 1))^p(a/b),
//     e_eff the saturation level of c_eff (below): the relaxation length shrinks with the slope of the
//     force-creepage curve as the contact saturates (the contact's tangential stiffness stays), and
//     each step is the steady model at c_eff (quasi-steady: the springs' own 2a memory is not used).
//     A first-order lag starts with a finite slope; the exact theory does not wherever a force needs the
//     material to roll in before it builds (Kalker: the lateral traction of spin's lateral rate phi x, the moment
//     of eta's lateral traction, both second order in q at a start). So eta and phi have a second stage,
//       d c_lag/dq = (c_eff - c_lag) / sigma2,  sigma2_k = s2_k(a/b) a (1 - min(e_eff, 1))^p(a/b),
//     (each step advanced in closed form, sigma held over the step), and the step is the steady model at c_eff
//     (as before: one creepage vector, so the mix corrections and the saturation stay consistent and the steady
//     map's peaks are not run through late) plus the second stage's share, linear in the levels u (below):
//       dFy = s(e_eff) A_phi(a/b) (u_phi,lag - u_phi,eff) mu N,
//       dMz = s(e_eff) [K_eta(a/b) (u_eta,lag - u_eta,eff) + K_phi(a/b) (u_phi,eff - u_phi,lag)] mu N sqrt(ab),
//     s(e) = (1 - min(e, 1))^2 the slope of the closed form 1 - (1 - e)^3 over its linear one. A_phi: the spin's
//     lateral force follows the second stage (A_phi its steady slope in u_phi, 3 g_phi in the linear range);
//     K_eta: eta's moment does; K_phi: the spin's moment leads its lateral force (the longitudinal rate phi y
//     builds it at once), and while the lateral traction builds from the leading edge it has a first moment
//     (2 x q phi / L3) that the steady state has not (the overshoot of the exact Mz under spin). Zero in the
//     steady state.
//     s_phi (first stage), s2, A, K: lib/tangential/relaxed_transient_table.h;
//   - steady forces: the simplified theory's force at a creepage is that of the exact theory at a
//     slightly different one: each creepage is scaled by a factor g_k(a/b, e) of the saturation level
//     e = G a b C |c| / (3 mu N) before the steady solve;
//   - spin: two flexibilities: phi scaled by g_phi(a/b, e) (its lateral rate phi x / L3: Fy) and its longitudinal
//     rate phi y / L3 by g_phix(a/b, e) (L3x = L3 g_phi / g_phix: Mz), fitted together to the exact Fy and Mz under
//     pure spin (one flexibility cannot hold both: Kalker's C23 and C33);
//   - mixes: the factors above are fitted on pure creepages; a mix of them adds to the creepages solved at a
//     correction d(a/b, direction, e) in levels (d_k times the creepage of level 1 in direction k, 3 mu N /
//     (G a b C_k)), fitted so that the exact Fx, Fy and Mz are met over the direction of the creepage vector
//     u = G a b (C11 xi, C22 eta, C23 sqrt(ab) phi) / (3 mu N): theta its angle from the xi axis, psi that of
//     (eta, phi) in their plane. The spin's correction has two parts, one in its lateral rate phi x / L3 and one
//     in its longitudinal rate phi y / L3: under pure eta they give the moment that the uniform rate eta / L2
//     lacks (the exact Mz under eta: the lateral traction's shape along x far from saturation, the turn of the
//     slip's direction across the contact near it). Without imposed spin (phi = 0) the march is kept free of
//     spin (its mirror skip and the cost of a solve without spin, lib/tangential/steady.h): the correction has
//     no spin parts there, and Mz is the march's plus a fitted moment (the traction field's own moment is the
//     march's; Mz does not enter the power when phi = 0). Pure xi: none;
//   - power: the exact theory's steady frictional power is the creep forces' work -V (xi Fx + eta Fy + phi Mz)
//     (docs/physics.md §4); the bed of springs with three flexibilities is not (1.5-2.2x with mixes).
//     The model keeps the strips' distribution of the simplified theory's power and scales it to that work
//     (with the work of the strips' Heathcote offsets, docs/physics.md §2.4, where the patch has them).
//   - contacts that are not elliptic (worn crowns): the flexibilities scaled by the patch's shape factor S and the
//     strips' shares of the power weighted towards the thin-contact limit (lib/tangential/relaxed_shape.h; no fit,
//     S = 1 on Hertz patches).
// The factors s_k and g_k: lib/tangential/relaxed_table.h, the mix corrections lib/tangential/relaxed_mix_table.h,
// fitted to the exact solver by
// scripts/fit-relaxed (fit error in docs/accuracy-vs-exact.md).
#pragma once

#include <limits>

#include "lib/elastic.h"
#include "lib/patch.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"

namespace contact {

// the effective creepages of a transient run (not the imposed ones): two stages in series (relaxed.h, transient)
struct RelaxedState {
  Creepages effective;   // first stage (the steady model is solved at it)
  Creepages lagged;      // second stage (eta, phi), relaxing towards the first: spin's Fy, eta's Mz, spin's Mz
  Creepages sigma_m;     // first-stage relaxation lengths in place of the table's where > 0 (for the fit)
  double exponent = -1;  // the exponent p in place of the table's if >= 0 (for the fit)
  Creepages sigma2_m;    // second-stage lengths (eta, phi) in place of the table's where > 0 (for the fit)
  double moment_eta = std::numeric_limits<double>::quiet_NaN();  // K_eta in place of the table's if finite (fit)
  double moment_phi = std::numeric_limits<double>::quiet_NaN();  // K_phi in place of the table's if finite (fit)
  double force_phi = std::numeric_limits<double>::quiet_NaN();   // A_phi in place of the table's if finite (fit)
};

inline RelaxedState relaxed_rest() { return {}; }
// the steady state at the creepages c (both stages at the imposed creepages)
inline RelaxedState relaxed_steady_state(const Creepages& c) {
  RelaxedState s;
  s.effective = c;
  s.lagged = c;
  return s;
}

// the first stage's relaxation lengths (m) of xi, eta and phi on a contact of semi-axes a_m (along rolling), b_m
// (linear, before the shrink with saturation)
Creepages relaxation_lengths_m(double a_m, double b_m);
// the second stage's (eta and phi; xi has none: 0)
Creepages second_stage_lengths_m(double a_m, double b_m);

// the saturation level e = G a b C11 |xi| / (3 mu N) at which the model under xi alone is as saturated as the
// simplified theory at e = 1 (Johnson and Vermeulen's saturation creepage; the same force, without Heathcote
// offsets): the simplified theory it solves is at its own level e g_x(a/b, e) / S there (S the shape factor), so
// this is the root of e g_x(a/b, e) = S: about 0.6 on Hertz patches (the exact theory saturates before the
// simplified theory's e = 1). 1 where there is no contact.
double relaxed_xi_saturation_level(const ContactPatch& patch);

// the model's slope dFx/dxi at xi -> 0 over the simplified theory's on the patch: g_x(a/b, 0) / S (its creepage
// factor at the lowest level, held below it, over the shape factor); 1 where there is no contact
double relaxed_xi_slope_factor(const ContactPatch& patch);

// the steady model: forces, fields, per-strip power (scaled to the creep forces' work), creep work.
// Throws std::invalid_argument as make_tangential_problem.
TangentialSolution solve_relaxed_steady(const ContactPatch& patch, const ElasticPair& pair, const Creepages& creepages,
                                        double mu, double speed_m_per_s, bool fields = true);

// A mix correction in levels: added to the creepages solved at, each times the creepage of level 1 in its
// direction (3 mu N / (G a b C_k)); the spin's in its lateral rate phi x / L3 and its longitudinal one phi y / L3
// separately
struct RelaxedMix {
  double xi = 0, eta = 0, phi_lateral = 0, phi_longitudinal = 0;
  double moment = 0;  // without imposed spin (the spin's parts 0 then): added to the march's Mz, times mu N sqrt(ab)
};
// the mix correction the table gives at the creepages c (zero for pure xi)
RelaxedMix relaxed_mix_correction(const ContactPatch& patch, const ElasticPair& pair, const Creepages& creepages,
                                  double mu);
// the steady model with the mix correction `mix` in place of the table's (for the fit, scripts/fit-relaxed)
TangentialSolution solve_relaxed_steady_with_mix(const ContactPatch& patch, const ElasticPair& pair,
                                                 const Creepages& creepages, const RelaxedMix& mix, double mu,
                                                 double speed_m_per_s, bool fields = false);

// One step rolling dq_m >= 0 with the imposed creepages c (the step's mean): the effective creepages
// relax, c_eff <- c + (c_eff - c) exp(-dq / sigma), and the second stage with them (closed form, sigma at the
// step's start), then the steady model at c_eff with the second stage's force and moments.
// Its power is the steady model's at c_eff (-V c_eff . F); creep_work_W is that of the imposed creepages.
TangentialSolution relaxed_step(const ContactPatch& patch, const ElasticPair& pair, const Creepages& creepages,
                                double mu, double speed_m_per_s, double dq_m, RelaxedState& state,
                                bool fields = false);

// The 'transient' run of a case with the relaxed model: the steps of Satran's shift scheme (dq = dx,
// shortened to the longest step dt_s or to land on t_end_s; the creepages and speed at mid-step, the
// contact at the step's end), each one relaxed_step. Hertz contact from the bodies (or c.patch at its
// constant load). Scheme shift only (SettingError naming `scheme` otherwise). The balance residual is nan.
// With settings.skip_steady (the wear loop's duty cycles), once the inputs are constant and the effective
// creepages are the imposed ones to a saturation level of 1e-10, the rest of the constant stretch is one
// record (shift_run.h, ShiftSkip). With c.inertia, run_relaxed_inertia.
TransientResult run_relaxed_transient(const TransientCase& c, const StepObserver& observe = {});

// The roller's inertia (RollerInertia, satran.h) with the relaxed model: steps of at most dt_s and at most
// dx rolled; each balances the roller's spin implicitly as Satran's inertia step does,
//   J1 (omega_end - omega1) = (-R1 Fx - T_res) dt,  V = (omega_mid R1 + V2)/2,  xi = (V2 - omega_mid R1)/V,
// omega_mid = (omega1 + omega_end)/2, V2 at mid-step, Fx that of relaxed_step at xi over dq = V dt. Records are
// the step's end; steps shorter than dx are not upwind fallbacks here (the model has no nodes to carry).
TransientResult run_relaxed_inertia(const TransientCase& c, const StepObserver& observe = {});

}  // namespace contact
