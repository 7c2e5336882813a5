#pragma once
// The one way this folder includes toml++: as declarations only, with the implementation
// compiled once in toml_impl.cpp instead of inline in every file (it is a large header).
// Only .cpp files of src/talus/io include this; no public header exposes toml++.
#ifndef TOML_HEADER_ONLY
#define TOML_HEADER_ONLY 0
#endif
#include <toml++/toml.h>
