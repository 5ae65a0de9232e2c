#pragma once
// The results of a forward run: an HDF5 file (format "dda-results", laid out
// in docs/formats.md) with the measurement-point time series, per-step
// statistics, block states at the output interval, the blocks the run
// started from, and a checkpoint of the whole simulation state from which a
// run continues exactly (`dda df --resume`). ParaView series of blocks and
// contacts are written alongside, frame by frame.
//
// run_recorded() drives a Simulation to its end (run_loop.hpp) and rewrites
// the results file atomically every so often (a temporary file renamed into
// place), so an interrupted run leaves the last complete file, ready to resume.
#include <csignal>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dda/common/block_model.hpp"
#include "dda/common/provenance.hpp"
#include "dda/df/core/run_loop.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {

// The state of every block at one output time.
struct Frame {
  int step = 0;
  double time = 0;                  // s
  std::vector<Vec2> vertices;       // all blocks one after another (block order, as in the model)
  std::vector<Vector6d> velocity;   // per block: end velocity of the last step [u, v, r, ex, ey, gxy] rates
  std::vector<Vector3d> stress;     // per block: [sx, sy, txy], Pa
};
Frame make_frame(const Simulation& sim);

// Where a run came from (root attributes of the results file).
struct ResultsSource {
  Provenance provenance;                // scenario path and full text, seed, program version
  std::string input_kind = "scenario";  // "scenario" (YAML) or "ana" (DDA for Windows analysis XML)
  std::string blocks_path;              // the blocks file as given
};

struct Results {
  ResultsSource source;
  BlockModel blocks;                    // the blocks the run started from
  std::string solver = "auto";
  OutputSchedule output;                // resolved
  std::vector<Frame> frames;            // frame 0 is the initial state

  // Filled by read_results_h5 (the writer takes them from the Simulation).
  bool complete = false;                // the run reached its end
  std::size_t block_count = 0;          // blocks of the model (also when the parts read leave `blocks` empty)
  std::vector<std::string> point_names; // measurement points, in model order
  std::vector<int> point_blocks;
  std::vector<StepRecord> log;
  std::vector<std::vector<MeasurementSample>> histories;  // per point; sample 0 is the initial state
  bool has_acceleration = false;        // the file holds /series/acceleration (older files do not)
  std::vector<EnergyRecord> energy;                       // record 0 is the initial state, then one per step
  std::vector<std::string> bolt_names;
  std::vector<std::vector<BoltSample>> bolt_histories;    // per bolt; sample 0 is the initial state
  std::optional<SimulationState> checkpoint;
};

// Writes everything (atomically) with the log, histories and checkpoint of `sim`.
void write_results_h5(const std::string& path, const Results& results, const Simulation& sim, bool complete);

// The parts of a results file a reader asks for (2D and 3D). A long run's
// file is mostly its per-step records (the 86,735 steps of a 20 s incline
// fill 26 MB with the log, the energy record and the point series), so a
// reader that needs one of them leaves the rest on disk.
struct ResultsParts {
  bool series = true;      // the measurement points and their histories
  bool log = true;         // the per-step log
  bool energy = true;      // the energy record (2D; 3D files have none)
  bool bolts = true;       // the bolt histories
  bool frames = true;      // the blocks the run started from and the block frames
  bool checkpoint = true;  // the state a run resumes from (needs frames)

  static ResultsParts all() { return {}; }
  // The series, log, energy and bolts, not the blocks (`dda history`, `dda info`).
  static ResultsParts records() {
    ResultsParts p;
    p.frames = p.checkpoint = false;
    return p;
  }
  static ResultsParts none() { return {false, false, false, false, false, false}; }
};

// Reads a results file, the parts asked for; InputError naming the file for
// anything wrong in what it reads. The root attributes and the block count
// are always read.
Results read_results_h5(const std::string& path, const ResultsParts& parts = ResultsParts::all());

// ParaView: blocks (polygons; cell data block_id, material, displacement of
// the centroid, velocity, rotation_rate, stress; point data displacement)
// and contacts (one vertex cell at the contact vertex; cell data state
// 0 open / 1 sliding / 2 locked, normal, normal_force, shear_force,
// vertex_block, edge_block, joint).
void write_blocks_frame_vtu(const std::string& path, const Simulation& sim);
void write_contacts_vtu(const std::string& path, const Simulation& sim);
// Both of a frame (the contacts unless `contacts_path` is empty): the hook
// of the ParaView series of `dda df` (tools/src/df_outputs.hpp).
void write_frame_vtu(const Simulation& sim, const Results& results, const std::string& blocks_path,
                     const std::string& contacts_path);

using RunControl = BasicRunControl<Simulation>;

// Steps `sim` to the end of its Control (total_time, or steps), saving a
// frame on the schedule of `results.output` and rewriting `path` on the
// schedule of `control`, and once more at the end. `results.frames` grows.
// A RunawayError (runaway.hpp) from a step is rethrown after the results
// up to the step before it are written.
RunEnd run_recorded(Simulation& sim, Results& results, const std::string& path, const RunControl& control);

// Fraction of the run done, 0..1 (time or steps).
double run_progress(const Simulation& sim);

// The hooks of run_recorded_loop (run_loop.hpp) for the 2D solver.
bool run_finished(const Simulation& sim);
void run_step(Simulation& sim);
int last_step(const Simulation& sim);
void write_results(const std::string& path, const Results& results, const Simulation& sim, bool complete);

}  // namespace dda::df
