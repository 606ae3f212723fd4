// Dang Van's index on a wear life's final worn contact (docs/fatigue.md §4c): for each body with
// bodies.bodyN.dang_van: { a, b_Pa }, the case's steady contact is solved once more on the life's final worn
// profiles, with the case's own models and running condition (lib/io/case_run.h solve_contact_case, as
// `rollwear contact` solves it, but with the life's friction coefficient: with a lubricant: section the regime
// law's, where `rollwear contact` solves with friction.mu), and Dang Van's criterion is evaluated over one
// rolling pass below that body (lib/subsurface/dang_van.h, subsurface_of_contact). A load collective: each condition's contact, the largest
// index of each body and the condition it comes from. At the end of the life only: one evaluation costs
// about as much as `rollwear contact` with dang_van (seconds), too much for every step or a located limit.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "lib/subsurface/dang_van.h"

namespace wear {

struct WearCase;
struct WearModel;

struct LifeDangVan {
  int body = 0;         // 1 or 2
  int condition = 0;    // a collective's condition with the largest index, 1-based as wear.collective[k] in the
                        // messages; 0 for the case's own running condition
  contact::DangVanField field;  // index_max and where (y in the profiles' coordinate, as strips.csv's)
};

// whether any body of the case has bodies.bodyN.dang_van
bool has_dang_van(const WearCase& c);

// the bodies' indices on the state's worn profiles (empty without dang_van); throws what solve_contact_case
// throws (contact::SolverError for an unconverged solve)
std::vector<LifeDangVan> dang_van_on_worn(const WearModel& m, const WearCase& c, const Eigen::VectorXd& state);

}  // namespace wear
