// The errors that decide the exit status, and the one mapping from error to status:
//   0 success; 2 bad input (a case file, an option, the state of the output folder the user named):
//   CaseError, whose message names the file, line and key; 1 any other failure, among them a solver's
//   (a std::invalid_argument thrown inside a solver is the solver's failure on valid input, not bad input).
// The decision is on the type, never on the message's text.
#pragma once

#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

namespace contact {

constexpr int kExitSuccess = 0;
constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

// Where bad input was found, as data (the message says it too): the file, the 1-based line and column
// (0 when not known) and the key path ("friction.mu"; "" when not one key). A reader that knows the
// place fills it; a cross-key check that only has the message's "FILE:LINE:COL: " prefix leaves it empty.
struct InputLocation {
  std::string file;
  int line = 0, column = 0;
  std::string key;
};

// bad input: "FILE:LINE:COL: key.path: what"; `location` the same place as data (the Python bindings'
// InputError attributes read it, never the message)
struct CaseError : std::runtime_error {
  using std::runtime_error::runtime_error;
  CaseError(const std::string& message, InputLocation where) : std::runtime_error(message), location(std::move(where)) {}
  InputLocation location;
};

// a solver (or the program) failed on input that passed validation: exit 1 with its cause
struct SolverError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A setting refused by a model's own check, with the setting's key as data: `key` relative to `section`
// ("kth.pressure_ratio" in "wear"), `problem` what is wrong ("must be in (0, 1], got 2"). It is a
// std::invalid_argument for callers that do not care; the case reader puts it at the key's line without
// reading the message back. what() is "section.key: problem".
struct SettingError : std::invalid_argument {
  SettingError(const std::string& section_, const std::string& key_, const std::string& problem_)
      : std::invalid_argument((section_.empty() ? key_ : section_ + "." + key_) + ": " + problem_),
        section(section_), key(key_), problem(problem_) {}
  std::string section, key, problem;
};

// A time step that breaks the CFL condition V dt/dx <= 1 of a fixed-step scheme, its numbers as data.
struct CflBreach : SettingError {
  CflBreach(const std::string& key_, const std::string& problem_, double dt_s_, double v_max_m_per_s_, double dx_m_)
      : SettingError("", key_, problem_), dt_s(dt_s_), v_max_m_per_s(v_max_m_per_s_), dx_m(dx_m_) {}
  double dt_s, v_max_m_per_s, dx_m;
};

// the exit status of an error that ends a command
inline int exit_status_of(const std::exception& e) {
  return dynamic_cast<const CaseError*>(&e) != nullptr ? kExitBadInput : kExitFailure;
}

// a value as a message may quote it: whole up to max_chars characters, else its first max_chars and
// "… (N bytes)", so that an error never echoes a multi-megabyte line
inline std::string clipped(const std::string& text, std::size_t max_chars = 80) {
  if (text.size() <= max_chars) return text;
  std::size_t cut = max_chars;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return text.substr(0, cut) + "… (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace contact
