#include "wear/dang_van_life.h"

#include <algorithm>
#include <array>

#include "lib/io/case_run.h"
#include "wear/wear_case.h"
#include "wear/wear_loop.h"

namespace wear {

bool has_dang_van(const WearCase& c) {
  return c.contact.bodies.body1.dang_van.has_value() || c.contact.bodies.body2.dang_van.has_value();
}

std::vector<LifeDangVan> dang_van_on_worn(const WearModel& m, const WearCase& c, const Eigen::VectorXd& state) {
  std::vector<LifeDangVan> out;
  if (!has_dang_van(c)) return out;
  const contact::Profiles worn = worn_profiles(m, state);
  // the case's own running condition, or each of a collective's (its load, kinematics and friction)
  std::vector<const contact::ContactCase*> cases;
  if (c.wear.collective.empty()) cases.push_back(&c.contact);
  for (const WearCondition& k : c.wear.collective) cases.push_back(&k.contact);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    contact::ContactCase worn_case = *cases[i];
    worn_case.profiles->profiles = worn;  // a wear case has profiles (validate)
    const contact::ContactRun run = contact::solve_contact_case(worn_case, true);  // the tractions' fields
    const std::array<contact::BodySubsurface, 2> below = contact::subsurface_of_contact(worn_case, run);
    for (int k = 0; k < 2; ++k) {
      if (!below[k].dang_van) continue;
      const int condition = c.wear.collective.empty() ? 0 : static_cast<int>(i) + 1;
      auto seen = std::find_if(out.begin(), out.end(), [&](const LifeDangVan& d) { return d.body == k + 1; });
      if (seen == out.end())
        out.push_back({k + 1, condition, *below[k].dang_van});
      else if (below[k].dang_van->index_max > seen->field.index_max)
        *seen = {k + 1, condition, *below[k].dang_van};
    }
  }
  return out;
}

}  // namespace wear
