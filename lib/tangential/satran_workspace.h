// What Satran's run driver (satran_run.cpp) asks of a step's workspace beyond satran.h: whether the
// workspace's last step was on a given patch, and to forget that patch. An inertia step's trials each
// step a copy of the state, and the workspace may take the nodes outside the contact as clear only for
// the state it stepped itself (SatranWorkspace in satran.h; defined in satran_step.cpp).
#pragma once

#include "lib/tangential/satran.h"

namespace contact {

// the workspace's last step was on the patch of this serial (SatranWorkspace::patch_serial)
bool workspace_stepped_on(const SatranWorkspace& ws, unsigned long patch_serial);
// the next step takes its patch as new: it clears the nodes outside the contact itself
void workspace_forget_patch(SatranWorkspace& ws);

}  // namespace contact
