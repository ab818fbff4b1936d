#include "io/json_reader.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace epviz::io {

nlohmann::json read_json_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw JobError(path.string() + ": cannot open the file for reading");
  std::stringstream text;
  text << in.rdbuf();
  try {
    auto j = nlohmann::json::parse(text.str());
    if (!j.is_object()) throw JobError(path.string() + ": the job must be a JSON object {...}");
    return j;
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the offset of the failure; turn it into line:column for the user.
    const std::string s = text.str();
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < s.size(); ++i) {
      if (s[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    throw JobError(path.string() + ":" + std::to_string(line) + ":" + std::to_string(col) +
                   ": not valid JSON");
  }
}

ObjectReader::ObjectReader(const nlohmann::json& object, std::string file, std::string path)
    : object_(&object), file_(std::move(file)), path_(std::move(path)) {}

std::string ObjectReader::where(const std::string& key) const {
  return file_ + ": key '" + (path_.empty() ? key : path_ + "." + key) + "'";
}

void ObjectReader::fail(const std::string& key, const std::string& what) const {
  throw JobError(where(key) + ": " + what);
}

bool ObjectReader::has(const std::string& key) const { return object_->contains(key); }

std::optional<std::string> ObjectReader::peek_string(const std::string& key) const {
  auto it = object_->find(key);
  if (it == object_->end() || !it->is_string()) return std::nullopt;
  return it->get<std::string>();
}

const nlohmann::json* ObjectReader::get(const std::string& key) {
  read_.insert(key);
  auto it = object_->find(key);
  return it == object_->end() ? nullptr : &*it;
}

std::optional<double> ObjectReader::number(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_number()) fail(key, "expected a number, got " + v->dump());
  const double x = v->get<double>();
  if (!std::isfinite(x)) fail(key, "expected a finite number");
  return x;
}

std::optional<double> ObjectReader::positive_number(const std::string& key) {
  auto x = number(key);
  if (x && !(*x > 0.0)) fail(key, "expected a positive number, got " + object_->at(key).dump());
  return x;
}

std::optional<long> ObjectReader::integer(const std::string& key, long min_value, long max_value) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_number_integer()) fail(key, "expected an integer, got " + v->dump());
  const long x = v->get<long>();
  if (x < min_value || x > max_value)
    fail(key, "expected an integer from " + std::to_string(min_value) + " to " +
                  std::to_string(max_value) + ", got " + std::to_string(x));
  return x;
}

std::optional<bool> ObjectReader::boolean(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_boolean()) fail(key, "expected true or false, got " + v->dump());
  return v->get<bool>();
}

std::optional<std::string> ObjectReader::string(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_string()) fail(key, "expected a string, got " + v->dump());
  return v->get<std::string>();
}

std::optional<std::string> ObjectReader::choice(const std::string& key,
                                                const std::vector<std::string>& allowed) {
  auto s = string(key);
  if (!s) return s;
  for (const auto& a : allowed)
    if (a == *s) return s;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  fail(key, "'" + *s + "' is not one of: " + list);
}

std::optional<std::array<double, 3>> ObjectReader::vec3(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_array() || v->size() != 3)
    fail(key, "expected an array of 3 numbers, got " + v->dump());
  std::array<double, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!(*v)[i].is_number()) fail(key, "expected an array of 3 numbers, got " + v->dump());
    out[i] = (*v)[i].get<double>();
  }
  return out;
}

std::optional<ObjectReader> ObjectReader::object(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_object()) fail(key, "expected an object {...}, got " + v->dump());
  return ObjectReader(*v, file_, path_.empty() ? key : path_ + "." + key);
}

void ObjectReader::finish() const {
  for (auto it = object_->begin(); it != object_->end(); ++it) {
    if (read_.count(it.key())) continue;
    std::string allowed;
    for (const auto& k : read_) allowed += (allowed.empty() ? "" : ", ") + k;
    fail(it.key(), "unknown key (allowed here: " + allowed + ")");
  }
}

}  // namespace epviz::io
