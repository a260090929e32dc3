#pragma once
// The exceptions the library throws. Library code never prints or exits: apps catch these
// and turn them into one line on stderr and an exit code.
#include <stdexcept>
#include <string>

namespace gsp {

// Base of everything the toolkit throws on purpose.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The caller handed over data that cannot be processed (NaN coordinates, indices out of
// range, a source vertex that does not exist, options that contradict each other).
struct InvalidInput : Error {
  using Error::Error;
};

// A file could not be read or written. `where` names the place (line, byte offset,
// accessor) so the message can point at it.
struct IoError : Error {
  IoError(const std::string& file, const std::string& place, const std::string& what_wrong)
      : Error(file + (place.empty() ? "" : ":" + place) + ": " + what_wrong),
        path(file), where(place), problem(what_wrong) {}
  std::string path, where, problem;
};

// An algorithm needs a structure the mesh does not have (e.g. exact geodesics on a
// non-manifold mesh).
struct TopologyError : Error {
  using Error::Error;
};

}  // namespace gsp
