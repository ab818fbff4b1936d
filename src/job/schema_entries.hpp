#pragma once
// How the job formats (job/schema.hpp, job/job_file.hpp) declare their keys:
// one table per object, each entry saying what a key is (for help and
// messages), how it is read into a document and how it is written from it.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json_reader.hpp"
#include "job/schema.hpp"

namespace epviz::job::entries {

using Json = nlohmann::ordered_json;

// A choice's allowed values for help and messages: "a, b, c".
std::string joined(const std::vector<std::string>& v);

// One key of an object in a job: what it is (for help and messages), how it
// is read into `Doc` and how it is written from it. An object's entry has
// children instead, and an optional check of the object once they are read.
template <class Doc>
struct Entry {
  KeyInfo info;  // info.path: the key within its object
  std::function<void(io::ObjectReader&, Doc&)> read;
  std::function<void(const Doc&, Json&)> write;  // sets its key, or leaves it out
  std::vector<Entry> children = {};
  std::function<void(const io::ObjectReader&, const Doc&)> check = {};
};

template <class Doc>
void read_entries(const std::vector<Entry<Doc>>& entries, io::ObjectReader& r, Doc& doc) {
  for (const auto& e : entries) {
    if (e.children.empty()) {
      e.read(r, doc);
      continue;
    }
    if (auto o = r.object(e.info.path)) {
      read_entries(e.children, *o, doc);
      o->finish();
      if (e.check) e.check(*o, doc);
    }
  }
}

template <class Doc>
void write_entries(const std::vector<Entry<Doc>>& entries, const Doc& doc, Json& out) {
  for (const auto& e : entries) {
    if (e.children.empty()) {
      e.write(doc, out);
      continue;
    }
    Json o = Json::object();
    write_entries(e.children, doc, o);
    if (!o.empty()) out[e.info.path] = std::move(o);
  }
}

template <class Doc>
void list_keys(const std::vector<Entry<Doc>>& entries, const std::string& prefix,
               std::vector<KeyInfo>& out) {
  for (const auto& e : entries) {
    KeyInfo k = e.info;
    k.path = prefix + k.path;
    out.push_back(k);
    list_keys(e.children, k.path + ".", out);
  }
}

}  // namespace epviz::job::entries
