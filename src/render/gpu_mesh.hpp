#pragma once
// A MeshData uploaded to GL (vertex array, vertex and index buffers).
#include <cstdint>

#include "render/gl.hpp"
#include "render/mesh_data.hpp"

namespace epviz::render {

class GpuMesh {
 public:
  GpuMesh() = default;
  explicit GpuMesh(const MeshData& mesh);  // needs a current GL context
  ~GpuMesh();
  GpuMesh(GpuMesh&& other) noexcept;
  GpuMesh& operator=(GpuMesh&& other) noexcept;
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  // Draws all triangles with the vertex array bound (attribute 0 position, 1 normal).
  void draw() const;
  std::int32_t index_count() const { return index_count_; }

 private:
  void release() noexcept;
  GLuint vao_ = 0;
  GLuint vertex_buffer_ = 0;
  GLuint index_buffer_ = 0;
  std::int32_t index_count_ = 0;
};

}  // namespace epviz::render
