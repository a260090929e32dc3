#pragma once
// What a CVT run needs per working-mesh face, to refuse a site count whose working mesh the
// machine cannot hold before it is built (gsp/available_memory.hpp says why).
namespace gsp::cvt::detail {

// Peak bytes of a CVT run per working-mesh face (the working mesh, GSP's solver and query
// state, labels, the dual): measured 578-627 on spot at 370k-1.5M working faces (gsp-cvt
// --stats, memory.peak_bytes).
inline constexpr double kBytesPerWorkingFace = 650;

}  // namespace gsp::cvt::detail
