// Field definitions and their build: depth-first over references, with the
// recursion stack giving the exact loop when a cycle is found.
#include "field/field_set.h"

#include <algorithm>

#include <fmt/format.h>

#include "field/error.h"

namespace sm::field {

const SizeField* BuiltFields::get(int id) const {
  auto it = fields_.find(id);
  return it == fields_.end() ? nullptr : it->second.get();
}

FieldPtr BuiltFields::shared(int id) const {
  auto it = fields_.find(id);
  return it == fields_.end() ? nullptr : it->second;
}

std::vector<int> BuiltFields::ids() const {
  std::vector<int> v;
  for (const auto& [id, f] : fields_) v.push_back(id);
  return v;
}

void FieldSet::define(int id, std::string_view kind) {
  const KindSpec* spec = find_kind(kind);
  if (!spec) {
    std::vector<std::string> names;
    for (const KindSpec& k : kinds()) names.push_back(k.name);
    FieldError e(FieldErrc::UnknownKind, fmt::format("unknown field type '{}'", kind));
    e.field_id = id;
    e.name = kind;
    e.suggestion = closest_name(kind, names);
    throw e;
  }
  if (contains(id)) {
    FieldError e(FieldErrc::DuplicateId, fmt::format("Field[{}] is already defined", id));
    e.field_id = id;
    throw e;
  }
  defs_.emplace(id, Options(*spec));
}

void FieldSet::remove(int id) { defs_.erase(id); }

const Options& FieldSet::options(int id) const {
  auto it = defs_.find(id);
  if (it == defs_.end()) {
    FieldError e(FieldErrc::MissingField, fmt::format("Field[{}] is not defined", id));
    e.field_id = id;
    e.ids = {id};
    throw e;
  }
  return it->second;
}

void FieldSet::set(int id, std::string_view option, OptionValue value) {
  auto it = defs_.find(id);
  if (it == defs_.end()) {
    FieldError e(FieldErrc::MissingField, fmt::format("Field[{}] is not defined", id));
    e.field_id = id;
    e.ids = {id};
    e.option = std::string(option);
    throw e;
  }
  try {
    it->second.set(option, std::move(value));
  } catch (FieldError& e) {
    e.field_id = id;
    throw;
  }
}

int FieldSet::next_id() const { return defs_.empty() ? 1 : defs_.rbegin()->first + 1; }

std::vector<int> FieldSet::ids() const {
  std::vector<int> v;
  for (const auto& [id, o] : defs_) v.push_back(id);
  return v;
}

void FieldSet::build_into(int id, const BuildContext& ctx, BuiltFields& out,
                          std::vector<int>& stack) const {
  if (out.fields_.count(id)) return;
  const Options& opts = options(id);
  // References first, so a cycle is reported as such before anything is built.
  // Finding them may parse (MathEval's F<n>): its errors name this field too.
  std::vector<int> refs;
  try {
    refs = referenced_ids(opts);
  } catch (FieldError& e) {
    if (e.field_id < 0) e.field_id = id;
    throw;
  }
  for (int ref : refs) {
    auto on_stack = std::find(stack.begin(), stack.end(), ref);
    if (ref == id || on_stack != stack.end()) {
      std::vector<int> loop(on_stack, stack.end());
      loop.push_back(id);
      loop.push_back(ref);
      if (ref == id) loop = {id, id};
      std::string text;
      for (std::size_t i = 0; i < loop.size(); ++i)
        text += fmt::format("{}Field[{}]", i ? " -> " : "", loop[i]);
      FieldError e(FieldErrc::Cycle, fmt::format("fields reference each other in a cycle: {}", text));
      e.field_id = id;
      e.ids = loop;
      throw e;
    }
    if (!contains(ref)) {
      FieldError e(FieldErrc::MissingField,
                   fmt::format("Field[{}] ({}) references Field[{}], which is not defined", id,
                               opts.kind().name, ref));
      e.field_id = id;
      e.ids = {ref};
      throw e;
    }
    stack.push_back(id);
    build_into(ref, ctx, out, stack);
    stack.pop_back();
  }
  BuildInputs in{id, opts, ctx, [&](int ref, std::string_view) -> FieldPtr {
                   // Every reference was built above; a kind asking for an
                   // undeclared one is a bug in that kind.
                   FieldPtr f = out.shared(ref);
                   if (!f) {
                     FieldError e(FieldErrc::MissingField,
                                  fmt::format("Field[{}] references Field[{}], which is not defined",
                                              id, ref));
                     e.field_id = id;
                     e.ids = {ref};
                     throw e;
                   }
                   return f;
                 }};
  // The kind's own set-up time (its references were built above, each in its own stage).
  struct SetupStage {
    Progress* p;
    ~SetupStage() { progress_end(p); }
  } stage{ctx.setup_clock};
  progress_begin(ctx.setup_clock, "field " + opts.kind().name, 0);
  try {
    out.fields_.emplace(id, opts.kind().make(in));
  } catch (FieldError& e) {
    if (e.field_id < 0) e.field_id = id;
    throw;
  }
}

BuiltFields FieldSet::build(int root, const BuildContext& ctx) const {
  BuiltFields out;
  std::vector<int> stack;
  build_into(root, ctx, out, stack);
  return out;
}

BuiltFields FieldSet::build_all(const BuildContext& ctx) const {
  BuiltFields out;
  for (const auto& [id, o] : defs_) {
    std::vector<int> stack;
    build_into(id, ctx, out, stack);
  }
  return out;
}

}  // namespace sm::field
