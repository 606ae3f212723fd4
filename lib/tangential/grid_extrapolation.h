// Richardson extrapolation of Kalker's exact steady solution over two grids (docs/exact-theory.md §4, "Grid
// extrapolation"): the same patch solved on its own grid (cell h) and on half the cells each way (2h, pairs of
// cells merged: the same load, the same strips' Heathcote offsets), combined as
//   Q = Q_h + (Q_h - Q_2h)/(2^p - 1)
// for the forces, the moment, the creep work and the power (p: the order of the discretisation's leading
// error, 1: the upwind transport of Kalker's steady discretisation, docs/exact-theory.md §2). The per-strip and
// per-cell power are the fine grid's times one factor, the extrapolated power over the fine one: their sum is
// the extrapolated creep work, their distribution the fine grid's (its shape converges faster than its level,
// which carries the first-order error nearly alike in every strip; per-strip Richardson over the pairs of
// strips was measured and is worse at the contact's lateral edges).
#pragma once

#include "lib/patch.h"
#include "lib/solve_status.h"
#include "lib/tangential/exact.h"
#include "lib/tangential/tangential.h"

namespace contact {

// the order p of the exact steady solution's leading grid error (docs/exact-theory.md §4)
constexpr double kExactGridOrder = 1.0;

struct ExtrapolatedExactSolution {
  // the fine grid's fields with Fx, Fy, Mz, creep_work_W and power_W extrapolated, strip_power_W_per_m and
  // power_W_per_m2 scaled to the extrapolated power; tractions, slips, strip forces and the stick fraction are
  // the fine grid's
  TangentialSolution fields;
  ExactSolution fine, coarse;  // the two solves (fine.fields as solved)
  SolveStatus status;          // the fine solve's, or the coarse one's when that did not converge
};

// Kalker's exact steady solution on the patch's grid, extrapolated in the grid with the coarse solve on
// halved_patch(patch). Arguments as solve_exact_steady's; order > 0 and finite, else std::invalid_argument
// (as for nx, ny odd or below 4). An unconverged solve: its status, fields not extrapolated (the fine ones).
ExtrapolatedExactSolution solve_exact_steady_extrapolated(const ContactPatch& patch, double G_Pa, double nu,
                                                          const Creepages& creepages, double mu, double speed_m_per_s,
                                                          double order = kExactGridOrder,
                                                          const ExactOptions& opt = {});

}  // namespace contact
