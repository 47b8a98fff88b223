// MSH 2.2 / 4.1 ASCII reader (msh_reader.h): a token scanner that knows its line, one
// function per section.
#include "io/msh_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>

namespace sm::io {
namespace {

// A failure at the scanner's line.
struct ReadError {
  std::string message;
  std::size_t line;
};

// Whitespace-separated tokens of the text, with the line of the last one read.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}
  bool at_end() {
    skip_space();
    return pos_ >= text_.size();
  }
  std::string_view token() {
    skip_space();
    if (pos_ >= text_.size()) fail("the file ends early");
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  // The rest of the current line (a quoted name with spaces).
  std::string_view rest_of_line() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    return text_.substr(start, pos_ - start);
  }
  double number() {
    const std::string_view t = token();
    double v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
      fail(fmt::format("'{}' is not a number", t));
    return v;
  }
  std::int64_t integer() {
    const std::string_view t = token();
    std::int64_t v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size()) fail(fmt::format("'{}' is not an integer", t));
    return v;
  }
  // A count of items that each take at least `tokens` more tokens: refused when the rest
  // of the text cannot hold them (a corrupt count must not allocate without bound).
  std::size_t count(std::size_t tokens) {
    const std::int64_t n = integer();
    if (n < 0 || static_cast<std::uint64_t>(n) * std::max<std::size_t>(tokens, 1) * 2 > text_.size() - pos_ + 1)
      fail(fmt::format("the count {} does not fit in the rest of the file", n));
    return static_cast<std::size_t>(n);
  }
  void expect(std::string_view word) {
    const std::string_view t = token();
    if (t != word) fail(fmt::format("expected '{}', found '{}'", word, t));
  }
  // Skips to the line after `$End<name>`.
  void skip_section(std::string_view name) {
    const std::string end = fmt::format("$End{}", name);
    for (;;)
      if (token() == end) return;
  }
  [[noreturn]] void fail(std::string message) const { throw ReadError{std::move(message), line_}; }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

ElementType element_type(Scanner& s, std::int64_t type) {
  switch (type) {
    case 15: return ElementType::Point1;
    case 1: return ElementType::Line2;
    case 2: return ElementType::Triangle3;
    case 3: return ElementType::Quad4;
    default:
      s.fail(fmt::format("element type {} is not read: only points (15), lines (1), triangles (2) and quadrangles "
                         "(3) are",
                         type));
  }
}

int dim_of(ElementType t) { return t == ElementType::Point1 ? 0 : t == ElementType::Line2 ? 1 : 2; }

// The blocks being read, by (dim, tag, type).
using BlockMap = std::map<std::tuple<int, int, int>, MshBlock>;

MshBlock& block_of(BlockMap& blocks, int dim, int tag, ElementType type) {
  MshBlock& b = blocks[{dim, tag, static_cast<int>(type)}];
  b.dim = dim, b.tag = tag, b.type = type;
  return b;
}

void read_physical_names(Scanner& s, MshFile& f) {
  const std::size_t n = s.count(3);
  for (std::size_t i = 0; i < n; ++i) {
    PhysicalGroup g;
    g.dim = static_cast<int>(s.integer());
    g.tag = static_cast<int>(s.integer());
    std::string_view name = s.rest_of_line();
    while (!name.empty() && (name.front() == ' ' || name.front() == '\t')) name.remove_prefix(1);
    while (!name.empty() && (name.back() == ' ' || name.back() == '\r')) name.remove_suffix(1);
    if (name.size() < 2 || name.front() != '"' || name.back() != '"') s.fail("a physical name is written in quotes");
    g.name = std::string(name.substr(1, name.size() - 2));
    f.physical_names.push_back(std::move(g));
  }
  s.expect("$EndPhysicalNames");
}

void read_nodes22(Scanner& s, MshFile& f) {
  const std::size_t n = s.count(4);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t tag = s.integer();
    const double x = s.number(), y = s.number(), z = s.number();
    if (tag <= 0 || !f.nodes.emplace(static_cast<std::uint64_t>(tag), Vec3{x, y, z}).second)
      s.fail(fmt::format("node tag {} is not positive or given twice", tag));
  }
  s.expect("$EndNodes");
}

// Node tag v of an element, which the file must have defined (its $Nodes come first).
std::uint64_t element_node(Scanner& s, const MshFile& f) {
  const std::int64_t v = s.integer();
  if (v <= 0 || !f.nodes.count(static_cast<std::uint64_t>(v)))
    s.fail(fmt::format("an element uses node {}, which the file does not define (before its elements)", v));
  return static_cast<std::uint64_t>(v);
}

void read_elements22(Scanner& s, const MshFile& f, BlockMap& blocks) {
  const std::size_t n = s.count(4);
  for (std::size_t i = 0; i < n; ++i) {
    s.integer();   // the element's number
    const ElementType type = element_type(s, s.integer());
    const std::size_t ntags = s.count(1);
    std::vector<std::int64_t> tags(ntags);
    for (auto& t : tags) t = s.integer();
    // Gmsh's MSH 2 tags: the physical group, then the elementary entity (then partitions).
    const int physical = ntags > 0 ? static_cast<int>(tags[0]) : 0;
    const int elementary = ntags > 1 ? static_cast<int>(tags[1]) : physical;
    if (elementary <= 0) s.fail(fmt::format("element {} has no elementary entity tag", i + 1));
    MshBlock& b = block_of(blocks, dim_of(type), elementary, type);
    if (physical > 0) b.physical_tags.push_back(physical);
    for (int k = 0; k < nodes_per_element(type); ++k) b.nodes.push_back(element_node(s, f));
  }
  s.expect("$EndElements");
}

// MSH 4.1's $Entities: the physical groups of each entity (by dim and tag).
void read_entities41(Scanner& s, std::map<std::pair<int, int>, std::vector<int>>& physicals) {
  std::size_t counts[4];
  for (auto& c : counts) c = s.count(5);
  for (int dim = 0; dim < 4; ++dim)
    for (std::size_t i = 0; i < counts[dim]; ++i) {
      const int tag = static_cast<int>(s.integer());
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) s.number();
      std::vector<int>& ph = physicals[{dim, tag}];
      const std::size_t np = s.count(1);
      for (std::size_t k = 0; k < np; ++k) ph.push_back(static_cast<int>(s.integer()));
      if (dim > 0) {
        const std::size_t nb = s.count(1);
        for (std::size_t k = 0; k < nb; ++k) s.integer();
      }
    }
  s.expect("$EndEntities");
}

void read_nodes41(Scanner& s, MshFile& f) {
  const std::size_t blocks = s.count(4);
  s.count(4);   // the number of nodes, then the smallest and largest tags
  s.integer(), s.integer();
  for (std::size_t b = 0; b < blocks; ++b) {
    const int dim = static_cast<int>(s.integer());
    s.integer();   // the entity's tag
    const bool parametric = s.integer() != 0;
    const std::size_t n = s.count(4);
    std::vector<std::uint64_t> tags(n);
    for (auto& t : tags) {
      const std::int64_t v = s.integer();
      if (v <= 0) s.fail(fmt::format("node tag {} is not positive", v));
      t = static_cast<std::uint64_t>(v);
    }
    for (std::uint64_t t : tags) {
      const double x = s.number(), y = s.number(), z = s.number();
      if (parametric)
        for (int k = 0; k < dim; ++k) s.number();
      if (!f.nodes.emplace(t, Vec3{x, y, z}).second) s.fail(fmt::format("node tag {} is given twice", t));
    }
  }
  s.expect("$EndNodes");
}

void read_elements41(Scanner& s, const MshFile& f, BlockMap& blocks,
                     const std::map<std::pair<int, int>, std::vector<int>>& physicals) {
  const std::size_t nblocks = s.count(4);
  s.count(2);
  s.integer(), s.integer();
  for (std::size_t k = 0; k < nblocks; ++k) {
    const int dim = static_cast<int>(s.integer());
    const int tag = static_cast<int>(s.integer());
    const ElementType type = element_type(s, s.integer());
    if (dim != dim_of(type))
      s.fail(fmt::format("an element block of dimension {} holds elements of type {}", dim, static_cast<int>(type)));
    if (tag <= 0) s.fail(fmt::format("element block on entity tag {}: tags are positive", tag));
    const std::size_t n = s.count(static_cast<std::size_t>(nodes_per_element(type)) + 1);
    MshBlock& b = block_of(blocks, dim, tag, type);
    if (const auto it = physicals.find({dim, tag}); it != physicals.end()) b.physical_tags = it->second;
    for (std::size_t i = 0; i < n; ++i) {
      s.integer();
      for (int j = 0; j < nodes_per_element(type); ++j) b.nodes.push_back(element_node(s, f));
    }
  }
  s.expect("$EndElements");
}

MshFile read_all(Scanner& s) {
  MshFile f;
  BlockMap blocks;
  std::map<std::pair<int, int>, std::vector<int>> physicals;
  s.expect("$MeshFormat");
  f.version = s.number();
  if (f.version != 2.2 && f.version != 4.1)
    s.fail(fmt::format("MSH version {} is not read: only 2.2 and 4.1 are", f.version));
  if (s.integer() != 0) s.fail("a binary MSH file is not read yet: save it as ASCII (Mesh.Binary = 0)");
  s.integer();   // the size of a double
  s.expect("$EndMeshFormat");
  while (!s.at_end()) {
    const std::string_view section = s.token();
    if (section.empty() || section[0] != '$') s.fail(fmt::format("expected a section, found '{}'", section));
    const std::string_view name = section.substr(1);
    if (name == "PhysicalNames") read_physical_names(s, f);
    else if (name == "Nodes" && f.version == 2.2) read_nodes22(s, f);
    else if (name == "Elements" && f.version == 2.2) read_elements22(s, f, blocks);
    else if (name == "Entities" && f.version == 4.1) read_entities41(s, physicals);
    else if (name == "Nodes") read_nodes41(s, f);
    else if (name == "Elements") read_elements41(s, f, blocks, physicals);
    else s.skip_section(name);
  }
  for (auto& [key, b] : blocks) {
    std::sort(b.physical_tags.begin(), b.physical_tags.end());
    b.physical_tags.erase(std::unique(b.physical_tags.begin(), b.physical_tags.end()), b.physical_tags.end());
    f.blocks.push_back(std::move(b));
  }
  return f;
}

}  // namespace

MshReadResult read_msh(std::string_view text) {
  MshReadResult r;
  Scanner s(text);
  try {
    r.file = read_all(s);
  } catch (const ReadError& e) {
    r.error = e.message;
    r.line = e.line;
  }
  return r;
}

}  // namespace sm::io
