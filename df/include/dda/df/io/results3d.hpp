#pragma once
// The results of a 3D forward run: an HDF5 file (format "dda-results3d",
// laid out in docs/formats.md) with the measurement-point time series, the
// step log, block states at the output interval, the blocks the run started
// from (under /model, as a dda-blocks3d file), and a checkpoint of the whole
// SimulationState3 from which a run continues exactly (`dda df --resume`).
// ParaView frames of polyhedra and contacts are written alongside.
//
// run_recorded() is the 2D loop (run_loop.hpp) over a Simulation3.
#include <optional>
#include <string>
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/df/io/results.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3 {

inline constexpr const char* kResults3dFormat = "dda-results3d";

// The state of every block at one output time.
struct Frame3 {
  int step = 0;
  double time = 0;                   // s
  std::vector<Vec3> vertices;        // all blocks one after another (block order)
  std::vector<Vector12d> velocity;   // per block: end velocity of the last step (the twelve rates)
  std::vector<Vector6d> stress;      // per block: [sx sy sz tyz tzx txy], Pa
};
Frame3 make_frame(const Simulation3& sim);

struct Results3 {
  df::ResultsSource source;            // provenance, input_kind "scenario", blocks_path
  PolyhedronModel blocks;              // the blocks the run started from
  df::OutputSchedule output;           // resolved
  std::vector<Frame3> frames;          // frame 0 is the initial state

  // Filled by read_results3_h5 (the writer takes them from the Simulation3).
  bool complete = false;
  std::vector<std::string> point_names;  // measurement points, in model order
  std::vector<int> point_blocks;
  std::vector<bool> fixed;               // per block: held fixed in the run
  std::vector<StepRecord3> log;
  std::vector<std::vector<MeasurementSample3>> histories;  // per point; sample 0 is the initial state
  std::vector<df::EnergyRecord> energy;  // record 0 is the initial state, then one per step; empty in older files
  std::vector<std::string> bolt_names;   // rock bolts, model order; none in a run without bolts
  std::vector<std::vector<df::BoltSample>> bolt_histories;  // per bolt; sample 0 is the initial state
  std::optional<SimulationState3> checkpoint;
};

// Writes everything (atomically) with the log, histories and checkpoint of `sim`.
void write_results3_h5(const std::string& path, const Results3& results, const Simulation3& sim, bool complete);

// Reads a 3D results file, the parts asked for (df::ResultsParts; a run
// without bolts has no /bolts, and files written before the 3D energy
// ledger no energy record); InputError naming the file for anything wrong in what it reads.
// The root attributes and /fixed are always read.
Results3 read_results3_h5(const std::string& path, const df::ResultsParts& parts = df::ResultsParts::all());

// ParaView: the blocks as VTK_POLYHEDRON cells at their current position
// (cell data block_id, fixed, displacement of the centroid, velocity,
// rotation_rate, stress (6, ParaView's order); point data displacement from
// `initial`, the blocks the run started from), and the contacts as vertex
// cells at the contact point (cell data state 0 open / 1 sliding / 2 locked,
// kind 0 vertex-face / 1 edge-edge, normal, normal_force, shear_force
// (vector, N), block_i, block_j, joint).
void write_blocks3_frame_vtu(const std::string& path, const Simulation3& sim, const std::vector<Polyhedron>& initial);
void write_contacts3_vtu(const std::string& path, const Simulation3& sim);
// Both of a frame (the contacts unless `contacts_path` is empty; the blocks'
// displacements from results.blocks): the hook of the ParaView series of
// `dda df` (tools/src/df_outputs.hpp).
void write_frame_vtu(const Simulation3& sim, const Results3& results, const std::string& blocks_path,
                     const std::string& contacts_path);

using RunControl3 = df::BasicRunControl<Simulation3>;

// Steps `sim` to the end of its Control3, with frames and atomic rewrites of
// `path` (run_loop.hpp). RunawayError is rethrown after the results up to
// the step before it are written.
df::RunEnd run_recorded(Simulation3& sim, Results3& results, const std::string& path, const RunControl3& control);

// Fraction of the run done, 0..1 (time or steps).
double run_progress(const Simulation3& sim);

// The hooks of run_recorded_loop for the 3D solver.
bool run_finished(const Simulation3& sim);
void run_step(Simulation3& sim);
int last_step(const Simulation3& sim);
void write_results(const std::string& path, const Results3& results, const Simulation3& sim, bool complete);

}  // namespace dda::df3
