// The methods radcache renders with, listed once (methods/registry.cpp): `--method`'s names, its
// help and the validation of method options all come from here.
#pragma once

#include <string>
#include <vector>

#include "methods/method.h"

namespace rc {

// Every method, in the order --help lists them.
const std::vector<MethodEntry>& method_registry();

// The method called `name`; Error (exit status 2) listing the methods otherwise.
const MethodEntry& find_method(const std::string& name);

// "pt, ic, ..." in registry order.
std::string method_names();

// Every method's options, each once, in registry order.
std::vector<OptionSpec> method_option_specs();

// Error (exit status 2) for the first option in `arguments` that belongs to other methods only:
// "--accuracy applies to --method ic only".
void refuse_foreign_options(const MethodEntry& method, const ParsedArguments& arguments);

// Error (exit status 2) for a requested layer the method does not have.
void check_layers(const MethodEntry& method, const std::vector<std::string>& layers);

}  // namespace rc
