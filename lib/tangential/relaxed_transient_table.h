// The relaxed model's transient law beyond the first stage (lib/tangential/relaxed.h, transient), fitted to
// Kalker's exact theory in-house: written by scripts/fit-relaxed --transient-only (do not edit by hand).
#pragma once

namespace contact::relaxed_transient_table {

constexpr int kNab = 5;
constexpr double kAb[kNab] = {0.0500, 0.1000, 0.3000, 1.0000, 3.0000};
// first-stage length / a of phi (the spin's longitudinal rate), second-stage lengths / a of eta and phi, and the
// transient moments K_eta, K_phi at each a/b (start-ups from rest under pure eta and pure phi, 40 x 40 cells)
constexpr double kSigmaPhi1[kNab] = {0.8500, 0.7200, 0.5400, 0.4000, 0.3300};
constexpr double kSigmaEta2[kNab] = {1.0000, 1.0000, 1.0000, 1.0000, 1.0000};
constexpr double kSigmaPhi2[kNab] = {2.1000, 1.8000, 1.3500, 1.0000, 0.8300};
constexpr double kMomentEta[kNab] = {0.0000, 0.0000, 0.0000, 0.0000, 0.0000};
constexpr double kMomentPhi[kNab] = {0.0000, 0.0000, 0.0000, 0.0000, 0.0000};

}  // namespace contact::relaxed_transient_table
