#pragma once
// One row per mesh of a corpus run (gsp-bench --corpus): what is left of a MeshRun once its
// mesh is gone (the run loads one mesh at a time), or the one-line reason the mesh failed.
#include "bench.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace gsp::bench {

struct CorpusMethod {
  std::string name;
  std::string skipped;       // why the method refused the mesh; empty when it ran
  double mre, max_re;        // against exact: mean over sources of the MRE, max; NaN without exact
  double signed_re = NAN;    // mean over sources of the signed mean relative error (< 0: short)
  double query_s;            // median time per query; NaN when skipped
  std::vector<double> source_mre;   // per source, in pick order; NaN where no exact reference
  BoundStats bounds;         // worst over sources (bounds.hpp)
  bool has_bounds = false;
};

struct CorpusRow {
  std::string name, path;
  std::string category = "unknown";   // benign | malign | unknown (categories.hpp)
  std::string status = "ok";          // ok | failed
  std::string reason;                 // failed: the error, on one line
  std::size_t vertices = 0, faces = 0, sources = 0;
  std::size_t exact_references = 0;   // sources with exact distances (errors measured)
  double steps_per_face;              // GSP: update steps per face reached, mean over sources
  std::vector<CorpusMethod> methods;  // in --methods order; empty when failed
  std::vector<std::string> notes;

  bool ok() const { return status == "ok"; }
  const CorpusMethod* method(const std::string& name) const;   // nullptr when not run
  double mre(const std::string& method_name) const;            // NaN when absent
};

CorpusRow corpus_row(const MeshRun& run, const std::string& category);
CorpusRow failed_row(const std::string& path, const std::string& category, const std::string& reason);

// GSP's MRE below the other method's: 1 yes, 0 no, -1 unknown (either has no MRE).
int gsp_beats(const CorpusRow& row, const std::string& other);

// GSP's MRE above the other's by more than kMreTie: less accurate, not a tie. On meshes where
// every vertex is an edge away from the source (a single triangle) Dijkstra is exact and GSP's
// single-precision state leaves an MRE of ~1e-8: rounding, not a loss.
constexpr double kMreTie = 1e-6;
bool gsp_worse(const CorpusRow& row, const std::string& other);
// The sources (with exact references for both) on which GSP's MRE is above the other's by
// more than kMreTie: the "below Dijkstra and heat on every mesh and source".
std::size_t gsp_worse_sources(const CorpusRow& row, const std::string& other);
std::size_t compared_sources(const CorpusRow& row, const std::string& other);

// GSP ran and broke a physical bound by more than 1%, or gave a NaN.
bool gsp_violates(const CorpusRow& row);

}  // namespace gsp::bench
