// A contact case read from a YAML document already parsed (a sweep's cases: the base case's document with
// some keys replaced, read without writing and parsing its text again, session/sweep.h). Kept out of
// lib/io/case.h so that the yaml-cpp node type stays out of that widely included header.
#pragma once

#include <filesystem>
#include <string>

#include <yaml-cpp/yaml.h>

#include "lib/io/case.h"

namespace contact {

// read_contact_case_text on a parsed document: `label` names it in messages; a value set in code has no
// line of its own (its messages name the closest enclosing key's)
ContactCase read_contact_case_node(const YAML::Node& doc, const std::string& label, const std::filesystem::path& base_dir,
                                   const ExtraSections& extra = {});

}  // namespace contact
