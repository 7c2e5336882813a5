// Compiles the toml++ implementation once for the library (see toml_include.h).
#define TOML_IMPLEMENTATION
#include "talus/io/toml_include.h"
