// Mesh.NodeData values (see node_data_export.h). The size is the one the mesher asks of
// a point inside a face: the background field with the channel widths of the coastlines
// inside its Min (size_policy_from_options.h), then Gmsh's factor and Min/Max clamp
// (field/size_policy.h). The criterion is the id of the Min's input that attains it.
#include "interp/kernel/node_data_export.h"

#include "field/min_max.h"
#include "field/size_policy.h"
#include "interp/interpreter.h"
#include "interp/kernel/field_context.h"
#include "interp/kernel/field_eval.h"
#include "interp/kernel/size_policy_from_options.h"
#include "interp/node_data_names.h"

namespace sm::interp {

std::string node_data_for_output(Interpreter& in, const io::MeshModel& mm, std::vector<io::NodeData>& out) {
  out.clear();
  std::string unknown;
  const std::vector<std::string> names = split_node_data_names(in.options().string("Mesh.NodeData"), &unknown);
  if (!unknown.empty()) return lang::format_diag(lang::Diag::NodeDataUnknownValue, unknown);
  return node_data_named(in, mm, names, out);
}

std::string node_data_named(Interpreter& in, const io::MeshModel& mm, const std::vector<std::string>& names,
                            std::vector<io::NodeData>& out) {
  out.clear();
  if (names.empty()) return {};
  const KernelState& k = in.kernel();
  const std::size_t n = mm.xyz.size();
  field::FieldPtr base, sized;
  std::vector<double> base_h, sized_h;
  auto sizes = [&]() -> std::string {
    if (sized) return {};
    base = background_size_field(in);
    sized = with_channel_sizes(in, base);
    if (!sized) return "Mesh.NodeData: size and criterion need a size field (Background Field = n, or a Coastline)";
    sized_h.resize(n);
    sized->eval(mm.xyz, sized_h);
    if (base) {
      base_h.resize(n);
      base->eval(mm.xyz, base_h);
    }
    return {};
  };
  for (const std::string& name : names) {
    std::vector<double> values(n);
    if (name == "depth") {
      if (!(in.options().number("Mesh.DepthField") > 0))
        return "Mesh.NodeData: depth needs Mesh.DepthField (a field giving the depth)";
      if (OptionRefusal r = depth_at(in, mm, values); !r.empty()) return r.message;
      out.push_back({name, "m", "depth at the mesh nodes (Mesh.DepthField), positive down", std::move(values)});
    } else if (name == "size") {
      if (std::string w = sizes(); !w.empty()) return w;
      const field::SizePolicyOptions policy = size_policy_from_options(in.options());
      field::SizeQuery q;
      q.bbox_diag = model_bbox_diag(k.model);
      q.entity_dim = 2;
      for (std::size_t i = 0; i < n; ++i) {
        q.background = sized_h[i];
        values[i] = field::final_size(policy, q).size;
      }
      out.push_back({name, "m", "target element size at the mesh nodes", std::move(values)});
    } else {   // criterion
      if (std::string w = sizes(); !w.empty()) return w;
      std::vector<int> which(n, -1);
      std::vector<double> h(n);
      // The Min itself, not the mesher's checked wrapper of it (background_size_field),
      // which hides its inputs from eval_argmin.
      const field::FieldPtr min =
          base ? built_fields(in, *k.background_field, k.background_field_at).shared(*k.background_field) : nullptr;
      const bool is_min = min && field::eval_argmin(*min, nullptr, mm.xyz, h, which);
      const int whole = base && k.background_field ? *k.background_field : -1;
      for (std::size_t i = 0; i < n; ++i) {
        // The coast's channel width is inside the Min only where it is smaller.
        const bool channel = !base || sized_h[i] < base_h[i];
        values[i] = channel ? 0 : (is_min ? which[i] : whole);
      }
      out.push_back({name, "1",
                     "size criterion at the mesh nodes: the field id in the background Min, 0 the channel width",
                     std::move(values)});
    }
  }
  return {};
}

}  // namespace sm::interp
