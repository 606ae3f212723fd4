// The relaxed model's transient law beyond the first stage (lib/tangential/relaxed.h, transient), fitted to
// Kalker's exact theory in-house: written by scripts/fit-relaxed --transient-only (do not edit by hand).
#pragma once

namespace contact::relaxed_transient_table {

constexpr int kNab = 5;
constexpr double kAb[kNab] = {0.0500, 0.1000, 0.3000, 1.0000, 3.0000};
// first-stage length / a of phi, second-stage lengths / a of eta and phi, and the second stage's force A_phi and
// moments K_eta, K_phi at each a/b (start-ups from rest under pure eta and pure phi, 40 x 40 cells)
constexpr double kSigmaPhi1[kNab] = {3.8000, 2.7000, 1.3000, 0.7000, 0.9000};
constexpr double kSigmaEta2[kNab] = {2.5500, 1.9000, 0.9000, 0.4500, 0.3500};
constexpr double kSigmaPhi2[kNab] = {0.3000, 0.4000, 0.6000, 1.7000, 0.8000};
constexpr double kForcePhi[kNab] = {-2.4800, -2.6000, -3.3600, -3.7800, -5.1600};
constexpr double kMomentEta[kNab] = {0.4400, 0.5200, 0.8000, 1.4800, 2.4400};
constexpr double kMomentPhi[kNab] = {-6.0000, -3.4600, -1.2000, -1.5200, -5.1600};

}  // namespace contact::relaxed_transient_table
