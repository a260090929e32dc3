#pragma once
// Sites fixed on the sharp features of the working mesh (CvtOptions::feature_angle): each crease
// curve sampled at even arc-length steps of about the site spacing, from corner to corner (a
// 1D CVT of constant density is even spacing, so the samples are its solution and never move),
// and the band of faces around each curve that always belongs to the curve's sites. The band
// keeps every free site's region off the curve, so consecutive samples are the only regions
// that meet along it and the dual has an edge between each pair: the curve as a chain of edges.
// A strip between two curves narrower than the band (a CAD part's chamfer or thin edge face)
// is shared out between the two curves' samples, with no free site inside: the dual zigzags
// across it.
#include "working_geometry.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace gsp::cvt::detail {

struct FeatureSites {
  std::vector<SurfaceSite> sites;        // fixed, at working vertices (corners exactly)
  // The band: the faces with a corner within band_width * spacing of a curve or a fixed
  // boundary corner (along the mesh edges), each with its sample (claim_feature_band).
  std::vector<std::pair<Index, Index>> band_faces;
  std::vector<Index> site_vertex;        // per site: its working vertex
  std::size_t curves = 0;                // curves kept (those at least one spacing long)
  std::size_t dropped_curves = 0;        // shorter curves, left to the free sites
};

// Crease curves by dihedral angle (detect_features), sampled with about `spacing` between
// samples (at least 3 steps on a closed curve). Curves shorter than `spacing` are dropped (scan
// noise; a crease shorter than an edge has no chain to keep). Boundary curves are left to the
// boundary sites, except the corners at the ends of those at least `spacing` long (where the
// boundary turns sharply or a crease meets it), which get fixed sites too: the boundary sites
// would cut them. A jagged scan boundary turns often but between corners a few edges apart.
FeatureSites feature_sites(const WorkingGeometry& g, double angle_deg, double spacing, double band_width);

// Spike tips (CvtOptions::cone_angle): the interior vertices of the working mesh whose angles
// sum to less than `max_angle_deg` but not less than half of it, the sharpest first, each at least `spacing` from every fixed site so far, at most `cap` of them,
// appended to f's sites (fixed, no band: the free sites' regions meet at the tip as
// anywhere). A cut-off tip is the remesh's largest distance from the input wherever the angle
// sum is far below 360 (the cut's depth grows as the cone narrows). A sharper tip is left to
// the free sites: so narrow a region meets too few others for the dual to give it a fan of
// triangles (square pyramids with apexes of 57-89 degrees lost their apex sites in the dual).
// Returns how many were added.
std::size_t add_cone_sites(const WorkingGeometry& g, double max_angle_deg, double spacing, std::size_t cap,
                           FeatureSites& f);

// Every face of the band takes its sample (the one, of its corners' samples nearest through
// the band, nearest its centroid): the band is shared out as the Voronoi regions of the
// samples (in a strip between two close curves, of both curves' samples). Returns the faces
// changed.
std::size_t claim_feature_band(const FeatureSites& f, std::vector<Index>& label);

}  // namespace gsp::cvt::detail
