// The Field[n] definitions of a script (id -> kind + option values) and their
// "build" into evaluable SizeFields with references resolved once.
#pragma once

#include <map>
#include <string_view>
#include <vector>

#include "field/options.h"
#include "field/registry.h"

namespace sm::field {

/// Fields built from a FieldSet: each id maps to one immutable SizeField
/// shared by every field that references it.
class BuiltFields {
 public:
  /// nullptr if `id` was not built.
  const SizeField* get(int id) const;
  FieldPtr shared(int id) const;
  std::vector<int> ids() const;

 private:
  friend class FieldSet;
  std::map<int, FieldPtr> fields_;
};

class FieldSet {
 public:
  /// `Field[id] = kind;`. Throws UnknownKind (with suggestion) or DuplicateId.
  void define(int id, std::string_view kind);
  /// `Delete Field[id];` (no-op if absent, as Gmsh).
  void remove(int id);
  /// `Field[id].option = value;`. Throws MissingField, UnknownOption, WrongOptionType.
  void set(int id, std::string_view option, OptionValue value);

  bool contains(int id) const { return defs_.count(id) != 0; }
  const Options& options(int id) const;
  /// `newf`: one more than the largest id in use (1 when empty).
  int next_id() const;
  std::vector<int> ids() const;

  /// Builds field `root` and everything it references. Throws MissingField
  /// (ids = {missing}), Cycle (ids = the loop, starting and ending at the
  /// same id) or the kind's own errors, all with field_id set.
  BuiltFields build(int root, const BuildContext& ctx) const;
  /// Builds every defined field, in increasing id order.
  BuiltFields build_all(const BuildContext& ctx) const;

 private:
  void build_into(int id, const BuildContext& ctx, BuiltFields& out, std::vector<int>& stack) const;

  std::map<int, Options> defs_;
};

}  // namespace sm::field
