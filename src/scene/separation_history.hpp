#pragma once
// The |Δγ| separation of one compared run from the first, as its chart keeps
// it: every sample while there are few, then a bounded, thinned history. The
// chart is a few hundred pixels wide, but a run's samples grow without end
// (the live mode has no last frame), so the samples are gathered into at
// most kBuckets stretches of equal length, halved in number (neighbours
// merged) whenever they are all full. Each stretch keeps its lowest and its
// highest sample, so that thinning hides no spike and no dip: the largest
// and the smallest separation of the whole run are always shown, at their
// own times, and the log axis the chart draws from the smallest stays put.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace epviz::scene {

class SeparationHistory {
 public:
  // Stretches kept at most; the points handed out are at most twice as many.
  static constexpr std::size_t kBuckets = 1024;  // even: merging leaves every stretch full
  static constexpr std::size_t kMaxPoints = 2 * kBuckets;

  // A sample (t, |Δγ|), t increasing from one call to the next. A separation
  // that is not a number counts as the highest (a run that lost the motion).
  void add(float t, float separation);

  // The points to draw, oldest first, t increasing: every sample
  // while there have been at most kBuckets, then each stretch's lowest and
  // highest in the order they came (from kBuckets + 1 to kMaxPoints points).
  std::vector<Eigen::Vector2f> points() const;

  std::size_t buckets() const { return buckets_.size(); }
  // Samples per full stretch: 1 until the first merge, then doubling.
  long stride() const { return stride_; }
  long samples() const { return samples_; }

 private:
  struct Bucket {
    Eigen::Vector2f low, high;  // (t, separation) of its lowest and highest sample
    long count = 0;             // samples gathered
  };
  void merge_neighbours();

  std::vector<Bucket> buckets_;
  long stride_ = 1;
  long samples_ = 0;
};

}  // namespace epviz::scene
