#pragma once
// The cloud of a render job (scene/cloud.hpp) integrated: its members'
// initial states, their gamma at every frame time by the batch integrator
// (sim/ensemble.hpp), and the spread of the cloud on the sphere.
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "physics/body.hpp"
#include "scene/cloud.hpp"
#include "sim/ensemble.hpp"
#include "sim/run_spec.hpp"

namespace epviz::scene {

struct ScenePlan;  // scene/plan.hpp

// The members' initial states. gamma: `members` points spread evenly by area
// over the cap of angular radius `radius` about the run's gamma (a sunflower
// pattern: member k at cos(theta) = 1 - (1 - cos radius) (k + 1/2) / N,
// azimuth k times the golden angle). Omega: the run's Omega scaled so that
// every member has the run's energy C1, so the cloud lies on one energy
// surface and its spread is the motion's, not a spread of energies. Throws
// PlanError (naming the "cloud" key) when a member's potential energy leaves
// it no kinetic energy (the run's Omega is zero, or the cap is too large).
std::vector<physics::InitialState> cloud_members(const physics::Body& body,
                                                 const physics::InitialState& centre,
                                                 const CloudSettings& cloud);

// The spread of points on the unit sphere: the fraction of the sphere's area
// they effectively cover, exp(H) / M, where H is the entropy of their
// histogram over M = kSpreadCells cells of equal area (24 bands equal in z
// times 48 in longitude). One cell's worth (1/M = 0.00087) for a small
// cloud; near 1 for points spread evenly over the whole sphere.
inline constexpr int kSpreadBands = 24, kSpreadSectors = 48;
inline constexpr int kSpreadCells = kSpreadBands * kSpreadSectors;
double cloud_spread(const std::vector<Eigen::Vector3f>& points);

// The cloud integrated as a render integrates it: DOP853 in the direct
// formulation, whatever the run's own method and formulation (the batch path
// has that one only), at sim::adaptive_tol of the run, every member to the
// `times` (ascending, from 0) on `threads` threads. The members go
// kCloudChunk at a time; each chunk's results (member `first` onwards, in
// order; a failed member's outputs end before its failure) are handed to
// `take` before the next chunk is integrated, so that memory holds one
// chunk's outputs. Each member's outputs are bitwise those of the scalar
// DOP853 on it alone (docs/ensembles.md).
inline constexpr std::size_t kCloudChunk = 1024;
using CloudChunkSink =
    std::function<void(std::size_t first, const std::vector<sim::DirectBatchResult>& results)>;
void integrate_cloud(const sim::RunSpec& run, const CloudSettings& cloud,
                     const std::vector<double>& times, int threads, const CloudChunkSink& take);

// The times a render's cloud is integrated to: its frames' (ScenePlan::frame_time).
std::vector<double> cloud_times(const ScenePlan& plan);

// A chunk's members as rows of their states: component c (Omega1..3, then
// gamma1..3, the direct formulation's order) of the chunk's member i at
// times[k] is state[c][i * times + k]; NaN from a member's failure on. Per
// member, when it failed (NaN: it did not) and how (numerics::name of the
// kind, "" for none).
struct CloudRows {
  std::size_t first = 0, members = 0, times = 0;
  std::array<std::vector<double>, 6> state;
  std::vector<double> failure_t;
  std::vector<std::string> failure_kind;
  long failed = 0;
};
CloudRows cloud_rows(std::size_t first, const std::vector<sim::DirectBatchResult>& results,
                     std::size_t times);

class CloudRun {
 public:
  // Integrates every member to the frame times (`threads` threads).
  CloudRun(const sim::RunSpec& run, const CloudSettings& cloud,
           const std::vector<double>& frame_times, int threads = 2);

  int members() const { return members_; }
  int frame_count() const { return int(gamma_.size()); }
  // gamma of each member that had not failed by frame `index`.
  const std::vector<Eigen::Vector3f>& gamma_at(int index) const {
    return gamma_[std::size_t(index)];
  }
  double spread_at(int index) const { return spread_[std::size_t(index)]; }
  // Frame `index` of the cloud, its spread from frame 0 to `index`
  // (`extent`: the plane panel's half-width).
  CloudFrame frame(int index, float extent) const;

 private:
  int members_ = 0;
  std::vector<double> times_;
  std::vector<std::vector<Eigen::Vector3f>> gamma_;  // [frame][member]
  std::vector<double> spread_;
};

}  // namespace epviz::scene
