#pragma once
// Shared check of a stretch ratio (internal).
namespace gsp::anisotropic::detail {

// Throws InvalidInput unless ratio is finite and > 0.
void check_ratio(double ratio);

}  // namespace gsp::anisotropic::detail
