#pragma once
// A compact JSON value written straight into a string, for records written by
// the thousand (a sweep's rows): no document tree and no allocation per key.
// Numbers are the shortest text that reads back to the same double (what
// nlohmann's dump writes too), an integral double keeps its ".0" so that it
// reads back as a floating-point number, and a non-finite double is written as
// null (JSON has no NaN or Inf). Keys and strings are escaped as JSON requires.
//
//   io::JsonLine j;
//   j.begin_object().key("t").value(1.5).key("v").begin_array().value(1L).end_array().end_object();
//   j.str()  ->  {"t":1.5,"v":[1]}
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace epviz::io {

class JsonLine {
 public:
  JsonLine& begin_object();
  JsonLine& end_object();
  JsonLine& begin_array();
  JsonLine& end_array();
  // The next member's key, inside an object.
  JsonLine& key(std::string_view k);

  JsonLine& value(double x);
  JsonLine& value(long x);
  JsonLine& value(int x) { return value(long(x)); }
  JsonLine& value(bool x);
  JsonLine& value(std::string_view s);
  JsonLine& value(const char* s) { return value(std::string_view(s)); }
  JsonLine& value(const std::string& s) { return value(std::string_view(s)); }
  JsonLine& null();
  // The number, or null when there is none.
  JsonLine& value(const std::optional<double>& x) { return x ? value(*x) : null(); }
  // A value already written as JSON (e.g. by nlohmann's dump), taken as it is.
  JsonLine& raw(std::string_view json);
  // Three doubles as an array.
  JsonLine& triple(double a, double b, double c);

  const std::string& str() const { return out_; }
  std::string take() { return std::move(out_); }

 private:
  void separate();           // the comma before a value or key that is not its container's first
  void open(char bracket);   // a container inside the current one
  void close(char bracket);  // the innermost open container
  std::string out_;
  std::vector<bool> first_;  // one entry per open container: nothing written in it yet
  bool after_key_ = false;
};

}  // namespace epviz::io
