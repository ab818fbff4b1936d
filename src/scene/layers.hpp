#pragma once
// What a picture draws, as layers in one table: each with its job key under
// "layers", its default, its help and its checkbox label in the live panel.
// The job's keys, the panel's checkboxes and the "at least one layer" rule
// loop over the table, so a new layer is one member, one enum value and one
// row here, and its painter.
#include <array>
#include <cstddef>
#include <initializer_list>

namespace epviz::scene {

enum class Layer { body, sphere, riccati, overlay };
inline constexpr std::size_t layer_count = 4;

// Which layers are on. Not an aggregate, so that no one builds it by
// position (a new layer would take the place of another): it starts from the
// table's defaults, or from the layers named in Layers::only.
struct Layers {
  // The members the painter reads; layer_table() says what each is.
  bool body = false, sphere = false, riccati = false, overlay = false;

  Layers();  // each layer as its default
  static Layers only(std::initializer_list<Layer> on);

  bool& operator[](Layer l);
  bool operator[](Layer l) const;
  bool any() const;  // a picture needs at least one layer
};

struct LayerInfo {
  Layer id;
  bool Layers::*member;
  const char* key;  // under a job's "layers"
  bool default_on;
  const char* help;
  const char* panel_label;
};

// Every layer, in the order of the enum, the job's keys and the panel.
const std::array<LayerInfo, layer_count>& layer_table();

}  // namespace epviz::scene
