#pragma once
// The cloud of a render job (scene/cloud.hpp) integrated: its members'
// initial states, their gamma at every frame time by the batch integrator
// (sim/ensemble.hpp), and the spread of the cloud on the sphere.
#include <vector>

#include "physics/body.hpp"
#include "scene/cloud.hpp"
#include "sim/ensemble.hpp"
#include "sim/run_spec.hpp"

namespace epviz::scene {

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
