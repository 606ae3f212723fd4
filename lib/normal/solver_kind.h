// Which normal solver produced a contact: data, never read back from a message (lib/normal/normal.h
// chooses it).
#pragma once

namespace contact {

enum class NormalSolverKind { Hertz, SemiHertz, Halfspace };

// "hertz", "semi-hertz", "halfspace": the names of the case's solver.normal and of the reports
inline const char* to_string(NormalSolverKind k) {
  switch (k) {
    case NormalSolverKind::Hertz: return "hertz";
    case NormalSolverKind::SemiHertz: return "semi-hertz";
    case NormalSolverKind::Halfspace: return "halfspace";
  }
  return "unknown";
}

}  // namespace contact
