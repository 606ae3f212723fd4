// The stresses below a contact's surface (docs/subsurface.md): the grid's piecewise-constant pressure and
// tangential tractions, each cell a uniformly loaded rectangle (lib/subsurface/rectangle_stress.h), summed
// into the stress tensor on planes parallel to the surface (an FFT convolution per plane) or at single
// points (a direct sum), with the maxima of von Mises, Tresca, the orthogonal shear stress and the principal
// stresses and where they lie. Any normal and tangential solution gives the tractions: Hertz, semi-Hertz
// and half-space patches alike, and every tangential model.
//
// Each body is a half-space of its own Poisson's ratio under the tractions it carries: body 1 the patch's
// pressure and the solution's tractions (which act on it), body 2 the same pressure and the tractions
// reversed. Axes: the grid's x (rolling) and y, and the depth z >= 0 into the body (for body 2 the z of
// docs/physics.md §1, for body 1 its opposite, which reverses the signs of sigma_xz and sigma_yz).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "lib/grid.h"
#include "lib/patch.h"
#include "lib/subsurface/rectangle_stress.h"
#include "lib/tangential/tangential.h"

namespace contact {

struct SurfaceTractions {
  Grid grid;
  Eigen::ArrayXXd pressure_Pa;             // (nx x ny) cell means, >= 0, pushing into the body
  Eigen::ArrayXXd shear_x_Pa, shear_y_Pa;  // (nx x ny) cell means acting on the body; empty: frictionless
};

// the tractions body 1 or body 2 carries: the patch's cell pressures and the solution's tractions (on body 1;
// reversed on body 2); solution null or without fields: frictionless. Throws std::invalid_argument for a
// body other than 1 or 2 or fields of another shape than the grid's.
SurfaceTractions surface_tractions(const ContactPatch& patch, const TangentialSolution* solution, int body);

// the stress at (x, y, z), z >= 0, by a direct sum over the loaded cells (nu: the body's Poisson's ratio)
StressTensor stress_at(const SurfaceTractions& t, double nu, double x_m, double y_m, double z_m);

// the stress on the plane at depth z_m at every cell centre
struct StressPlane {
  double z_m = 0;
  Eigen::ArrayXXd xx, yy, zz, xy, xz, yz;  // (nx x ny), Pa, tension positive
  StressTensor at(int i, int j) const { return {xx(i, j), yy(i, j), zz(i, j), xy(i, j), xz(i, j), yz(i, j)}; }
};

// the planes at the given depths (each >= 0), by FFT convolution of the cells' tractions with the rectangle
// solutions at the cell-centre offsets (exact for the piecewise-constant tractions, to rounding)
std::vector<StressPlane> stress_planes(const SurfaceTractions& t, double nu, const std::vector<double>& depths_m);

struct StressPeak {
  double value_Pa = 0;
  double x_m = 0, y_m = 0, z_m = 0;  // where: a cell centre, at the depth refined between the planes
};
struct SubsurfaceMaxima {
  StressPeak von_mises;         // the largest von Mises stress
  StressPeak tresca;            // the largest principal shear stress (sigma1 - sigma3)/2
  StressPeak orthogonal_shear;  // the largest |sigma_xz| (value_Pa: its amplitude)
  StressPeak tension;           // the largest principal stress sigma1 (tension positive)
  StressPeak compression;       // the smallest principal stress sigma3 (value_Pa < 0 under load)
};

// The maxima over the planes' cells. A peak on an inner plane has its depth and value refined by the parabola
// through its plane and the two next to it (same cell); on the first or last plane it stays there. The planes
// must be evenly spaced and increasing (throws std::invalid_argument otherwise).
SubsurfaceMaxima subsurface_maxima(const std::vector<StressPlane>& planes, const Grid& grid);

// What one evaluation (a contact, a step of a life) computes: the planes from the surface to depth_m, evenly
// spaced, and their maxima; section_strip: the strip (column j) through the most loaded cell, whose x-z section
// is the field to plot.
struct SubsurfaceOptions {
  double depth_over_semi_axis = 1.5;  // deepest plane: this times the smaller semi-axis min(a, b)
  int planes = 31;                    // planes from the surface to the deepest (>= 3)
};
constexpr double kSubsurfaceDepthMax = 10;  // depth_over_semi_axis in (0, 10]
constexpr int kSubsurfacePlanesMax = 401;   // planes in [3, 401]
struct Subsurface {
  double nu = 0;
  std::vector<StressPlane> planes;
  SubsurfaceMaxima maxima;
  int section_strip = 0;
};
// throws std::invalid_argument for options out of range or a non-positive semi-axis
Subsurface solve_subsurface(const SurfaceTractions& t, double nu, double smaller_semi_axis_m,
                            const SubsurfaceOptions& options = {});

}  // namespace contact
