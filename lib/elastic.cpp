#include "lib/elastic.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace contact {

void check_material(const Material& m, const char* which) {
  if (!(m.E_Pa > 0) || !std::isfinite(m.E_Pa))
    throw std::invalid_argument(std::string(which) + ": Young's modulus must be positive and finite, got " +
                                std::to_string(m.E_Pa) + " Pa");
  if (!(m.nu >= 0 && m.nu < 0.5))
    throw std::invalid_argument(std::string(which) + ": Poisson's ratio must be in [0, 0.5), got " +
                                std::to_string(m.nu));
}

double shear_modulus_Pa(const Material& m) { return m.E_Pa / (2 * (1 + m.nu)); }

double effective_modulus_Pa(const ElasticPair& pair) {
  const Material& m1 = pair.body1;
  const Material& m2 = pair.body2;
  return 1 / ((1 - m1.nu * m1.nu) / m1.E_Pa + (1 - m2.nu * m2.nu) / m2.E_Pa);
}

double combined_shear_modulus_Pa(const ElasticPair& pair) {
  return 2 / (1 / shear_modulus_Pa(pair.body1) + 1 / shear_modulus_Pa(pair.body2));
}

double combined_poisson(const ElasticPair& pair) {
  const double G1 = shear_modulus_Pa(pair.body1);
  const double G2 = shear_modulus_Pa(pair.body2);
  return combined_shear_modulus_Pa(pair) * (pair.body1.nu / G1 + pair.body2.nu / G2) / 2;
}

}  // namespace contact
