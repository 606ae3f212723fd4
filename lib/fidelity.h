// The fidelity of a wear life (solver.fidelity, docs/fidelity.md): which physics evaluates its wear rate.
//   fast       the case's normal and tangential models as given (the defaults: semi-Hertz and relaxed)
//   corrected  the fast models, their per-node wear rate corrected by the exact physics (the half-space
//              normal problem and Kalker's exact theory) solved on the same worn state, on a schedule set by
//              how far the worn profile has moved since the last correction (wear/fidelity_correction.h)
//   exact      the exact physics at every evaluation (normal: halfspace, tangential: exact)
#pragma once

#include <stdexcept>
#include <string>

#include "lib/enum_names.h"

namespace contact {

enum class Fidelity { Fast, Corrected, Exact };

inline constexpr EnumTable<Fidelity, 3> kFidelityNames = {
    {{Fidelity::Fast, "fast"}, {Fidelity::Corrected, "corrected"}, {Fidelity::Exact, "exact"}}};

inline std::string to_string(Fidelity f) { return enum_name(kFidelityNames, f); }

inline Fidelity parse_fidelity(const std::string& name) {
  if (const std::optional<Fidelity> f = enum_from_name(kFidelityNames, name)) return *f;
  throw std::invalid_argument("unknown fidelity '" + name + "' (valid: " + enum_names_list(kFidelityNames) + ")");
}

}  // namespace contact
