// Elastic constants of the two bodies, and the combinations the contact problems use.
//
// Quasi-identity is assumed (docs/physics.md §1): the normal and tangential problems are uncoupled.
//   normal problem:      1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
//   tangential problem:  1/G  = (1/G1 + 1/G2)/2,   nu = G (nu1/G1 + nu2/G2)/2,   Gk = Ek/(2(1+nuk))
#pragma once

namespace contact {

struct Material {
  double E_Pa = 0;  // Young's modulus
  double nu = 0;    // Poisson's ratio, in [0, 0.5)
};

struct ElasticPair {
  Material body1;  // upper body (the roller); tractions act on it
  Material body2;  // lower body (the path)
};

// throws std::invalid_argument for E <= 0 or nu outside [0, 0.5)
void check_material(const Material& m, const char* which);

double shear_modulus_Pa(const Material& m);
double effective_modulus_Pa(const ElasticPair& pair);  // E*
double combined_shear_modulus_Pa(const ElasticPair& pair);  // G
double combined_poisson(const ElasticPair& pair);  // nu of the tangential problem

}  // namespace contact
