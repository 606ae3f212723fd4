// The relaxed model's factors (lib/tangential/relaxed.h), fitted to Kalker's exact theory in-house by
// scripts/fit-relaxed (placeholder: the identity, until the fit writes this file).
#pragma once

namespace contact::relaxed_table {

constexpr int kNab = 1;
constexpr double kAb[kNab] = {1.0};
// relaxation length / a of xi, eta, phi at each a/b
constexpr double kSigmaX[kNab] = {2.7};
constexpr double kSigmaY[kNab] = {2.7};
constexpr double kSigmaPhi[kNab] = {2.7};
// creepage factors over the saturation level e at each a/b
constexpr int kNe = 1;
constexpr double kE[kNe] = {0.0};
constexpr double kGx[kNab][kNe] = {{1.0}};
constexpr double kGy[kNab][kNe] = {{1.0}};
constexpr double kGphi[kNab][kNe] = {{1.0}};

}  // namespace contact::relaxed_table
