#include "lib/tangential.h"

#include <cmath>
#include <stdexcept>

namespace contact {

double mean_flexibility_m_per_Pa(const Flexibilities& f, const Creepages& c, double a_m, double b_m) {
  const double ab = a_m * b_m;
  const double norm = std::sqrt(c.xi * c.xi + c.eta * c.eta + c.phi_per_m * c.phi_per_m * ab);
  if (!(norm > 0)) return f.L1_m_per_Pa;
  return (f.L1_m_per_Pa * std::abs(c.xi) + f.L2_m_per_Pa * std::abs(c.eta) +
          f.L3_m_per_Pa * std::abs(c.phi_per_m) * std::sqrt(ab)) / norm;
}

TangentialProblem make_tangential_problem(const ContactPatch& patch, const ElasticPair& pair,
                                          const Creepages& creepages, double mu, double speed_m_per_s) {
  if (!(mu >= 0) || !std::isfinite(mu))
    throw std::invalid_argument("tangential: friction coefficient must be >= 0 and finite, got " + std::to_string(mu));
  if (!(speed_m_per_s >= 0) || !std::isfinite(speed_m_per_s))
    throw std::invalid_argument("tangential: rolling speed must be >= 0 and finite, got " +
                                std::to_string(speed_m_per_s) + " m/s");
  if (!std::isfinite(creepages.xi) || !std::isfinite(creepages.eta) || !std::isfinite(creepages.phi_per_m))
    throw std::invalid_argument("tangential: creepages must be finite");
  TangentialProblem p;
  p.C = kalker_coefficients(patch.a_m, patch.b_m, combined_poisson(pair));
  p.flex = kalker_flexibilities(p.C, patch.a_m, patch.b_m, combined_shear_modulus_Pa(pair));
  p.L_m_per_Pa = mean_flexibility_m_per_Pa(p.flex, creepages, patch.a_m, patch.b_m);
  p.creepages = creepages;
  p.mu = mu;
  p.speed_m_per_s = speed_m_per_s;
  return p;
}

std::string to_string(TangentialScheme scheme) {
  switch (scheme) {
    case TangentialScheme::Classic: return "classic";
    case TangentialScheme::Consistent: return "consistent";
  }
  return "unknown";
}

TangentialScheme parse_tangential_scheme(const std::string& name) {
  if (name == "consistent") return TangentialScheme::Consistent;
  if (name == "classic") return TangentialScheme::Classic;
  throw std::invalid_argument("unknown tangential scheme '" + name + "' (valid: consistent, classic)");
}

}  // namespace contact
