// The summary of a sweep (summary.txt, docs/sweeps.md, "Summaries"), built from the results table's text.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace session {

// The summary of a whole sweep's table (summary.txt), from results.csv's text and sweep.txt's:
//   random sampling: the life's B10 and B50 (Kaplan-Meier: a life that reached wear.revolutions or
//     max_steps is right-censored there) with 95 % percentile bootstrap intervals (kBootstrapResamples
//     resamples drawn by the project's generator from the sweep's seed), and Spearman's rank correlation
//     of each input with the life; cases whose status is not ok are counted apart and left out;
//   a product grid: d ln(life) / d ln(x) of each axis by central differences about the base case (the
//     grid point nearest the base case's values; one-sided at an axis' end), the other axes held there.
constexpr int kBootstrapResamples = 1000;

// The Kaplan-Meier estimate of the fraction of lives ended by a life t, from (life, censored) pairs (a
// censored life lasts at least that long): one step per distinct failure, F(t) = 1 - prod (1 - 1/at risk),
// failures ordered before censorings at a tie. summary.txt's B10 and B50 are its quantiles.
struct KaplanMeierStep {
  double life = 0;             // a failure's life
  double failed_fraction = 0;  // F just after it
};
std::vector<KaplanMeierStep> kaplan_meier(std::vector<std::pair<double, bool>> lives);
std::string sweep_summary(const std::string& results_csv, const std::string& sweep_txt);

}  // namespace session
