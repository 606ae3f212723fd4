// Which normal solver produced a contact: data, never read back from a message (lib/normal/normal.h
// chooses it).
#pragma once

#include "lib/enum_names.h"

namespace contact {

enum class NormalSolverKind { Hertz, SemiHertz, Halfspace };

// "hertz", "semi-hertz", "halfspace": the names of the case's solver.normal and of the reports
constexpr EnumTable<NormalSolverKind, 3> kNormalSolverKindNames = {{{NormalSolverKind::Hertz, "hertz"},
                                                                    {NormalSolverKind::SemiHertz, "semi-hertz"},
                                                                    {NormalSolverKind::Halfspace, "halfspace"}}};
inline const char* to_string(NormalSolverKind k) { return enum_name(kNormalSolverKindNames, k); }

}  // namespace contact
