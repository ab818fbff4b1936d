#include "scene/layers.hpp"

namespace epviz::scene {

const std::array<LayerInfo, layer_count>& layer_table() {
  static const std::array<LayerInfo, layer_count> table{{
      {Layer::body, &Layers::body, "body", true,
       "the body, its principal axes, fixed point and centre of mass", "body"},
      {Layer::sphere, &Layers::sphere, "sphere", true, "the unit sphere with the trail", "sphere"},
      {Layer::riccati, &Layers::riccati, "riccati", true, "the (a, b) plane panel", "(a, b) plane"},
      {Layer::overlay, &Layers::overlay, "overlay", true, "case, time, method and drifts",
       "info overlay"},
  }};
  return table;
}

Layers::Layers() {
  for (const auto& l : layer_table()) this->*l.member = l.default_on;
}

Layers Layers::only(std::initializer_list<Layer> on) {
  Layers layers;
  for (const auto& l : layer_table()) layers.*l.member = false;
  for (Layer l : on) layers[l] = true;
  return layers;
}

bool& Layers::operator[](Layer l) { return this->*layer_table()[std::size_t(l)].member; }
bool Layers::operator[](Layer l) const { return this->*layer_table()[std::size_t(l)].member; }

bool Layers::any() const {
  for (const auto& l : layer_table())
    if (this->*l.member) return true;
  return false;
}

}  // namespace epviz::scene
