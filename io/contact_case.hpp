// The `contact` section of a case -> the composed contact law (docs/cases.md, docs/contact.md). The papers'
// groups (k-hat, Gamma-bar, G_adh, gamma-hat) are accepted as the papers define them and converted here.
#pragma once
#include <yaml-cpp/yaml.h>

#include "dem/contact/contact_law.hpp"
#include "io/schema_reader.hpp"

namespace suspend::io {

// species: how many species the case has (particles.species), for contact.species_pairs.
ContactLaw read_contact(SchemaReader r, int species);
YAML::Node contact_to_yaml(const ContactLaw& law);
std::string contact_law_name(const ContactLaw& law);

}  // namespace suspend::io
