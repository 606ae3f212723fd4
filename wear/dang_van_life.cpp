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
  // and its model's friction coefficient: with a lubricant: section the regime law's (WearModel::regime), not friction.mu
  std::vector<std::pair<const contact::ContactCase*, double>> cases;
  if (c.wear.collective.empty()) cases.emplace_back(&c.contact, m.mu);
  for (std::size_t i = 0; i < c.wear.collective.size(); ++i)
    cases.emplace_back(&c.wear.collective[i].contact, m.conditions.at(i).mu);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    contact::ContactCase worn_case = *cases[i].first;
    worn_case.profiles->profiles = worn;  // a wear case has profiles (validate)
    worn_case.friction.mu = cases[i].second;
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
