// A case file (YAML) read into validated plain structs. One struct per section, YAML keys equal to
// the field names, defaults in-class. Every key the reader reads is marked; a key left over is an
// error, so a typo never becomes a silent default. Errors throw CaseError, whose message names the
// file, the line and column, and the key path:
//   cases/paper.yaml:12:5: friction.mu: must be in [0, 10], got -1
#pragma once

#include <map>
#include <stdexcept>
#include <string>

#include "lib/elastic.h"
#include "lib/grid.h"
#include "lib/hertz.h"
#include "lib/tangential.h"

namespace contact {

struct CaseError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct BodySection {                  // bodies.body1 / bodies.body2
  double Rx_m = kFlat, Ry_m = kFlat;  // required; .inf for flat, negative for concave
  double E_Pa = 0;                    // required
  double nu = 0;                      // required, [0, 0.5)
};
struct BodiesSection {
  BodySection body1;  // upper body (roller)
  BodySection body2;  // lower body (path)
};
struct LoadSection {
  double normal_load_N = 0;  // required, > 0
};
struct KinematicsSection {
  double speed_m_per_s = 1.0;  // rolling speed V >= 0
  double xi = 0, eta = 0, phi_per_m = 0;
};
struct FrictionSection {
  double mu = 0;  // required, >= 0
};
struct SolverSection {
  std::string tangential = "consistent";  // consistent | classic
  int nx = 80, ny = 80;
};
struct OutputSection {
  std::string directory;  // default: out/<case name>, relative to the working directory
  bool fields = true;     // write the fields on the grid (fields.csv)
};

// key path -> "FILE:LINE:COL" of each value read from the file ("bodies.body1.Rx_m" ->
// "cases/paper.yaml:6:17"), so that cross-key messages point at the file too
using KeyLocations = std::map<std::string, std::string>;

struct ContactCase {
  std::string path;  // the file it was read from
  std::string name;  // 'name:' or the file's stem
  BodiesSection bodies;
  LoadSection load;
  KinematicsSection kinematics;
  FrictionSection friction;
  SolverSection solver;
  OutputSection output;
  KeyLocations locations;  // where each value was read; empty for a case built in code
};

// reads and validates; throws CaseError (file, line, key) on any problem
ContactCase read_contact_case(const std::string& path);

// cross-key checks; throws CaseError naming every key involved
void validate(const ContactCase& c);

// conversions to the solvers' inputs
Bodies bodies_of(const ContactCase& c);
ElasticPair materials_of(const ContactCase& c);
Creepages creepages_of(const ContactCase& c);
GridSpec grid_of(const ContactCase& c);

}  // namespace contact
