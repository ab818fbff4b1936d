#include "scene/separation_history.hpp"

#include <cmath>

namespace epviz::scene {
namespace {

// Ties go to the earlier sample for the lowest and to the later one for the
// highest, so that a stretch of two or more samples keeps two distinct ones
// (its points keep t strictly increasing and their number is known).
bool lower_than(const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
  if (std::isnan(a.y())) return false;
  return std::isnan(b.y()) || a.y() < b.y();
}

bool at_least_as_high(const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
  if (std::isnan(a.y())) return true;
  return !std::isnan(b.y()) && a.y() >= b.y();
}

}  // namespace

void SeparationHistory::add(float t, float separation) {
  const Eigen::Vector2f p(t, separation);
  ++samples_;
  if (buckets_.empty() || buckets_.back().count == stride_) {
    if (buckets_.size() == kBuckets) merge_neighbours();
    // kBuckets is even: the merged stretches are all full, and p starts a new one.
    if (buckets_.empty() || buckets_.back().count == stride_) {
      buckets_.push_back({p, p, 1});
      return;
    }
  }
  Bucket& b = buckets_.back();
  if (lower_than(p, b.low)) b.low = p;
  if (at_least_as_high(p, b.high)) b.high = p;
  ++b.count;
}

void SeparationHistory::merge_neighbours() {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < buckets_.size(); i += 2) {
    Bucket merged = buckets_[i];
    if (i + 1 < buckets_.size()) {
      const Bucket& later = buckets_[i + 1];
      if (lower_than(later.low, merged.low)) merged.low = later.low;
      if (at_least_as_high(later.high, merged.high)) merged.high = later.high;
      merged.count += later.count;
    }
    buckets_[kept++] = merged;
  }
  buckets_.resize(kept);
  stride_ *= 2;
}

std::vector<Eigen::Vector2f> SeparationHistory::points() const {
  std::vector<Eigen::Vector2f> out;
  out.reserve(2 * buckets_.size());
  for (const Bucket& b : buckets_) {
    if (b.low.x() == b.high.x()) {
      out.push_back(b.low);  // one sample (or two whose times a float cannot tell apart)
    } else if (b.low.x() < b.high.x()) {
      out.push_back(b.low);
      out.push_back(b.high);
    } else {
      out.push_back(b.high);
      out.push_back(b.low);
    }
  }
  return out;
}

}  // namespace epviz::scene
