// The relaxed model's factors (lib/tangential/relaxed.h), fitted to Kalker's exact theory in-house:
// written by scripts/fit-relaxed 80 40 (do not edit by hand). Spin factors refitted (--spin-only).
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
// spin: the factor on phi (its lateral rate phi x / L3) and on its longitudinal rate phi y / L3 (pure spin's Fy, Mz)
constexpr double kGphi[kNab][kNe] = {{1.0109, 1.0501, 1.0522, 1.0585, 1.0585, 1.0585, 1.0585, 1.0585}, {0.9445, 0.9909, 1.1582, 1.1698, 1.1698, 1.2422, 1.1816, 1.1816}, {0.9655, 0.9909, 1.0459, 1.0501, 1.0501, 1.0501, 1.0522, 1.0211}, {0.9949, 0.9810, 1.0049, 1.4005, 1.3456, 1.3456, 1.3456, 1.3456}, {0.9869, 0.9771, 0.9655, 1.1398, 1.0417, 1.0129, 1.0293, 1.0564}};
constexpr double kGphiX[kNab][kNe] = {{0.7366, 0.7366, 0.7035, 0.6252, 0.5748, 0.5589, 0.5523, 0.5523}, {0.7515, 0.7605, 0.8239, 0.6923, 0.6468, 0.6327, 0.6177, 0.6152}, {0.8943, 0.9087, 0.8731, 0.7728, 0.7545, 0.7455, 0.7455, 0.7470}, {1.0989, 1.0685, 1.0793, 0.8748, 0.8108, 0.7884, 0.7884, 0.7995}, {1.4194, 1.3969, 1.4138, 0.7821, 0.6599, 0.6533, 0.6533, 0.6546}};

}  // namespace contact::relaxed_table
