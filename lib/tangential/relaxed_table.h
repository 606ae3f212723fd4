// The relaxed model's factors (lib/tangential/relaxed.h), fitted to Kalker's exact theory in-house:
// written by scripts/fit-relaxed 80 40 (do not edit by hand). 
#pragma once

namespace contact::relaxed_table {

constexpr int kNab = 5;
constexpr double kAb[kNab] = {0.0500, 0.1000, 0.3000, 1.0000, 3.0000};
// relaxation length / a of xi, eta, phi at each a/b (start-up from rest on 40 x 40 cells)
constexpr double kSigmaX[kNab] = {3.6500, 3.0500, 2.3000, 1.7000, 1.1530};
constexpr double kSigmaY[kNab] = {3.1000, 2.6000, 1.9500, 1.7000, 1.1530};
constexpr double kSigmaPhi[kNab] = {3.1000, 2.6000, 1.9500, 1.7000, 1.1530};
// the exponent p of sigma = sigma0 (1 - e_eff)^p at each a/b (xi's fit)
constexpr double kExponent[kNab] = {1.2500, 1.2500, 1.5000, 2.0000, 2.4560};
// creepage factors over the saturation level e = G a b C |c| / (3 mu N) at each a/b (steady, 80 x 80 cells)
constexpr int kNe = 8;
constexpr double kE[kNe] = {0.0500, 0.1000, 0.2000, 0.3000, 0.4000, 0.5500, 0.7000, 0.8500};
constexpr double kGx[kNab][kNe] = {{0.9800, 0.9620, 0.9580, 0.9960, 1.0800, 1.3980, 2.5800, 2.8720}, {0.9820, 0.9620, 0.9580, 0.9960, 1.0780, 1.3920, 2.5220, 2.7960}, {0.9820, 0.9620, 0.9540, 0.9900, 1.0660, 1.3600, 2.3340, 2.6440}, {0.9760, 0.9540, 0.9420, 0.9680, 1.0320, 1.2680, 1.9720, 2.6180}, {0.9700, 0.9460, 0.9300, 0.9500, 1.0020, 1.1940, 1.7080, 2.7620}};
constexpr double kGy[kNab][kNe] = {{0.9860, 0.9680, 0.9640, 1.0000, 1.0880, 1.4140, 2.6440, 2.8920}, {0.9820, 0.9620, 0.9560, 0.9940, 1.0740, 1.3800, 2.4760, 2.8340}, {0.9800, 0.9580, 0.9480, 0.9800, 1.0500, 1.3160, 2.1700, 2.7040}, {0.9760, 0.9540, 0.9380, 0.9620, 1.0180, 1.2300, 1.8200, 2.6620}, {0.9720, 0.9460, 0.9280, 0.9460, 1.0000, 1.1740, 1.6340, 2.6860}};
constexpr double kGphi[kNab][kNe] = {{1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000}, {1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000}, {1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000}, {1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000}, {1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000}};

}  // namespace contact::relaxed_table
