#pragma once
// Long calls run without the GIL; this is how they still report progress and stop on Ctrl-C.
// The library calls the returned function now and then (from the calling thread); it takes
// the GIL, lets Python run its signal handlers (KeyboardInterrupt then propagates out of the
// library call as an exception, unwinding it) and calls the user's callback, if any.
#include <pybind11/pybind11.h>

#include <functional>

namespace gsp::python {

std::function<void(double)> interruptible(pybind11::object progress);

}  // namespace gsp::python
