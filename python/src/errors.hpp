#pragma once
// The library's typed errors as Python exceptions: gsp::InvalidInput and gsp::TopologyError
// -> ValueError, gsp::IoError -> OSError, gsp::pathfinding::NoPath -> gsp.NoPathError, any
// other gsp::Error -> gsp.Error (a RuntimeError). And the package's warning category.
#include <pybind11/pybind11.h>

#include <string>

namespace gsp::python {

void register_errors(pybind11::module_& m);

// Issues gsp.RemeshWarning (a UserWarning) with `message`; needs the GIL. Raises (throws
// error_already_set) where the warnings filter turns it into an error.
void warn_remesh(const std::string& message);

// Raises gsp.NoPathError with `message` (for conditions found in the bindings).
[[noreturn]] void raise_no_path(const std::string& message);

}  // namespace gsp::python
