// The traction at one node of a strip: what the steady march (lib/tangential/strip_march.h) carries
// from node to node and what Satran's state (lib/tangential/satran.h) holds between steps.
#pragma once

namespace contact {

struct StripNode {
  double tx = 0, ty = 0;  // Pa
  double ex = 0, ey = 0;  // direction of tau, kept from the last slip (0 before any)
  bool stick = true;
};

}  // namespace contact
