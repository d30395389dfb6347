// SPDX-License-Identifier: GPL-2.0-or-later
// A small JSON value: built by the commands for their JSON form, parsed for run.json metadata.
// Objects keep insertion order so output is deterministic; non-finite numbers print as null.
#ifndef OHMDEM_POST_JSON_H
#define OHMDEM_POST_JSON_H

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace ohmdem::post {

class Json {
 public:
  enum class Type { Null, Bool, Number, String, Array, Object };

  Json() = default;
  Json(std::nullptr_t) {}
  Json(bool b) : type_(Type::Bool), bool_(b) {}
  Json(double d) : type_(Type::Number), num_(d) {}
  Json(int i) : type_(Type::Number), num_(i) {}
  Json(long i) : type_(Type::Number), num_(static_cast<double>(i)) {}
  Json(long long i) : type_(Type::Number), num_(static_cast<double>(i)) {}
  Json(unsigned long i) : type_(Type::Number), num_(static_cast<double>(i)) {}
  Json(unsigned long long i) : type_(Type::Number), num_(static_cast<double>(i)) {}
  Json(const char *s) : type_(Type::String), str_(s) {}
  Json(std::string s) : type_(Type::String), str_(std::move(s)) {}

  static Json array();
  static Json object();
  static Json parse(const std::string &text, const std::string &source = "JSON");

  Type type() const { return type_; }
  bool is_null() const { return type_ == Type::Null; }
  bool is_number() const { return type_ == Type::Number; }
  bool is_string() const { return type_ == Type::String; }
  bool is_object() const { return type_ == Type::Object; }
  bool is_array() const { return type_ == Type::Array; }
  double number() const { return num_; }
  bool boolean() const { return bool_; }
  const std::string &string() const { return str_; }

  // arrays
  Json &push_back(Json v);
  std::size_t size() const;
  const Json &operator[](std::size_t i) const { return items_.at(i); }
  // objects: set() replaces an existing key in place, else appends
  Json &set(const std::string &key, Json v);
  const Json *find(const std::string &key) const;
  const std::vector<std::pair<std::string, Json>> &members() const { return members_; }

  // indent < 0: one line; otherwise pretty-printed with that many spaces per level
  std::string dump(int indent = 2) const;

 private:
  void dump_to(std::string &out, int indent, int level) const;

  Type type_ = Type::Null;
  bool bool_ = false;
  double num_ = 0;
  std::string str_;
  std::vector<Json> items_;
  std::vector<std::pair<std::string, Json>> members_;
};

std::string json_number(double v);  // shortest round-trip text, "null" if not finite

}  // namespace ohmdem::post

#endif
