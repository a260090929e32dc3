#pragma once
// The library's typed errors as Python exceptions: gsp::InvalidInput and gsp::TopologyError
// -> ValueError, gsp::IoError -> OSError, gsp::pathfinding::NoPath -> gsp.NoPathError, any
// other gsp::Error -> gsp.Error (a RuntimeError).
#include <pybind11/pybind11.h>

namespace gsp::python {

void register_errors(pybind11::module_& m);

// Raises gsp.NoPathError with `message` (for conditions found in the bindings).
[[noreturn]] void raise_no_path(const std::string& message);

}  // namespace gsp::python
