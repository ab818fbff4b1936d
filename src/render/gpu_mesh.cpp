#include "render/gpu_mesh.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

namespace epviz::render {

GpuMesh::GpuMesh(const MeshData& mesh) {
  if (mesh.normals.size() != mesh.positions.size())
    throw std::invalid_argument("mesh needs one normal per position");
  // Interleaved position + normal: one buffer, one stream for the rasteriser.
  std::vector<float> vertices;
  vertices.reserve(mesh.positions.size() * 6);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const auto& p = mesh.positions[i];
    const auto& n = mesh.normals[i];
    vertices.insert(vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
  }
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vertex_buffer_);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)),
               vertices.data(), GL_STATIC_DRAW);
  glGenBuffers(1, &index_buffer_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glBindVertexArray(0);
  index_count_ = static_cast<std::int32_t>(mesh.indices.size());
  check_gl_error("uploading a mesh");
}

GpuMesh::~GpuMesh() { release(); }

GpuMesh::GpuMesh(GpuMesh&& other) noexcept
    : vao_(std::exchange(other.vao_, 0)),
      vertex_buffer_(std::exchange(other.vertex_buffer_, 0)),
      index_buffer_(std::exchange(other.index_buffer_, 0)),
      index_count_(std::exchange(other.index_count_, 0)) {}

GpuMesh& GpuMesh::operator=(GpuMesh&& other) noexcept {
  if (this != &other) {
    release();
    vao_ = std::exchange(other.vao_, 0);
    vertex_buffer_ = std::exchange(other.vertex_buffer_, 0);
    index_buffer_ = std::exchange(other.index_buffer_, 0);
    index_count_ = std::exchange(other.index_count_, 0);
  }
  return *this;
}

void GpuMesh::release() noexcept {
  if (vao_ != 0) glDeleteVertexArrays(1, &vao_);
  if (vertex_buffer_ != 0) glDeleteBuffers(1, &vertex_buffer_);
  if (index_buffer_ != 0) glDeleteBuffers(1, &index_buffer_);
  vao_ = vertex_buffer_ = index_buffer_ = 0;
  index_count_ = 0;
}

void GpuMesh::draw() const {
  if (index_count_ == 0) return;
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace epviz::render
