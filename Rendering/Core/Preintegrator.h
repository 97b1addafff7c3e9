// Monte-Carlo preintegration of the scattering table (ALGORITHM.md section 4).
//
// Setting: a ball of radius 1 (distances in units of r) with homogeneous extinction tau, albedo,
// Henyey–Greenstein phase g, vacuum outside, lit by a directional light propagating along +z with
// unit irradiance.
//
// A(theta): backward paths start at the exit point and go radially inwards. Free flights are
// sampled inside the ball (forced collisions: the escape probability is folded into the path
// weight), directions from the phase function, and at every vertex next-event estimation goes to
// the light with transmittance exp(-tau b). Because the path geometry does not depend on the
// light's direction, one path serves every theta node: the light's direction is rotated around
// the exit direction instead (one random azimuth per path). It does not depend on the albedo
// either: vertex k carries albedo^k, so one path serves every albedo node too. Paths end through
// Russian roulette on the albedo-free weight (unbiased).
//
// F: backward paths from the forward pole into the ball along cosine-distributed directions of
// the far hemisphere (the flux through the tangent plane), plus the direct beam exp(-2 tau).
//
// Each (tau, g) cell is traced in batches until every significant entry (>= 1e-3 of the table's
// largest value of A, or of F) has a relative standard error under the target, or the path budget
// is spent.
// Each batch has its own random stream derived from (seed, cell, batch): the result does not
// depend on the number of threads.
#ifndef avs_Preintegrator_h
#define avs_Preintegrator_h

#include "ScatteringTable.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace avs
{

struct PreintegrationSettings
{
  ScatteringTableAxes Axes;
  std::uint64_t Seed = 1;
  std::uint64_t BatchSize = 2048;        ///< paths per batch (for A and for F each)
  std::uint64_t MinimumPaths = 8192;     ///< per cell, before the error is checked
  std::uint64_t MaximumPaths = 1 << 18;  ///< per cell, for A
  std::uint64_t MaximumPathsF = 1 << 22; ///< per cell, for F (its paths are much cheaper)
  double TargetRelativeError = 0.008;    ///< stop a cell once all significant entries are below
  double SignificanceThreshold = 1e-3;   ///< relative to the table's largest A (or F)
  int Threads = 0;                       ///< 0: DefaultThreadCount()
  /// Optional subset of cells (tau index, g index) to compute; empty: all. Other cells stay 0.
  std::vector<std::pair<int, int>> Cells;
  /// Optional earlier table with the same axes to refine: its cells whose significant entries
  /// all meet TargetRelativeError are copied, the others are computed again from scratch with
  /// these settings (typically a larger path budget). With the same seed, a refined cell is the
  /// cell a single run with these settings would give. Ignored when the axes differ.
  const ScatteringTable* Refine = nullptr;
  /// Optional: called with the table so far (finished cells computed, the others as in Refine,
  /// or empty) at most every CheckpointSeconds, serialised, never with half a cell. Writing it
  /// out makes a long run resumable: refining the checkpoint skips the cells already done.
  std::function<void(const ScatteringTable&)> Checkpoint;
  double CheckpointSeconds = 600.0;
  /// Called with (cells done, cells in all) from the worker threads, serialised.
  std::function<void(std::size_t, std::size_t)> Progress;
};

struct PreintegrationStatistics
{
  std::uint64_t PathsA = 0;
  std::uint64_t PathsF = 0;
  std::uint64_t Vertices = 0;
  std::size_t CellsAtPathLimit = 0; ///< cells that stopped on MaximumPaths, not on the error
  std::size_t CellsComputed = 0;    ///< cells traced in this run (the others were copied)
};

/// Whether every significant entry of cell (tau index j, g index k) has a relative standard
/// error at most `target`. Significance as in the settings (relative to the table's largest A,
/// or to F = 1).
bool CellMeetsTarget(const ScatteringTable& table, int j, int k, double threshold, double target);

/// Runs the generator. Cells with tau = 0 are analytic: A = albedo p_g(cos theta), F = 1.
ScatteringTable Preintegrate(const PreintegrationSettings& settings,
  PreintegrationStatistics* statistics = nullptr);

} // namespace avs

#endif
