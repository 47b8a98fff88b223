// interp/kernel/statements: the table that sends each statement kind to its handler.
#include <doctest/doctest.h>

#include <cstddef>
#include <string>
#include <variant>

#include "interp/kernel/dispatch.h"
#include "interp/kernel/statements.h"
#include "interp_test_util.h"

using sm::interp::kernel_stmt_handler;
using sm::lang::StmtKind;

TEST_CASE("statements: the evaluator's kinds have no handler, every other kind has one") {
  // What interpreter.cpp runs itself (variables, control flow, Printf, Include, commands).
  const StmtKind core[] = {StmtKind::Assign, StmtKind::IncDec, StmtKind::DefineConstant, StmtKind::Delete,
                           StmtKind::Print,  StmtKind::If,     StmtKind::For,            StmtKind::Macro,
                           StmtKind::Call,   StmtKind::Return, StmtKind::Exit,           StmtKind::Abort,
                           StmtKind::Assert, StmtKind::Include, StmtKind::Command};
  for (std::size_t k = 0; k < std::variant_size_v<sm::lang::StmtNode>; ++k) {
    const auto kind = static_cast<StmtKind>(k);
    bool is_core = false;
    for (StmtKind c : core) is_core = is_core || c == kind;
    CAPTURE(k);
    CHECK((kernel_stmt_handler(kind) == nullptr) == is_core);
  }
}

TEST_CASE("statements: each family's rows name its handler") {
  CHECK((kernel_stmt_handler(StmtKind::FieldNew) == &sm::interp::exec_field_stmt));
  CHECK((kernel_stmt_handler(StmtKind::BackgroundField) == &sm::interp::exec_field_stmt));
  CHECK((kernel_stmt_handler(StmtKind::CoastlineNew) == &sm::interp::exec_coastline_stmt));
  CHECK((kernel_stmt_handler(StmtKind::CoastlineOption) == &sm::interp::exec_coastline_stmt));
  CHECK((kernel_stmt_handler(StmtKind::CoastlineAction) == &sm::interp::exec_coastline_stmt));
  CHECK((kernel_stmt_handler(StmtKind::DeleteCoastline) == &sm::interp::exec_coastline_stmt));
  CHECK((kernel_stmt_handler(StmtKind::Point) == &sm::interp::exec_geometry_stmt));
  CHECK((kernel_stmt_handler(StmtKind::SetFactory) == &sm::interp::exec_set_factory_stmt));
  CHECK((kernel_stmt_handler(StmtKind::Coherence) == &sm::interp::exec_coherence_stmt));
  CHECK((kernel_stmt_handler(StmtKind::Plugin) == &sm::interp::exec_plugin_stmt));
  CHECK((kernel_stmt_handler(StmtKind::View) == &sm::interp::exec_mesh_stmt));
}

TEST_CASE("statements: a field and a coastline statement reach their own family") {
  const auto field = sm::interp::testing::run_script("Field[1] = Threshold;\nField[1].Foo = 2;\n");
  REQUIRE(field.kinds.size() == 1);
  CHECK(field.kinds[0] == "2:10 unknown-field-option");
  const auto coast = sm::interp::testing::run_script("Coastline[1] = GSHHS;\nCoastline[1].Foo = 2;\n");
  REQUIRE(coast.kinds.size() == 1);
  CHECK(coast.kinds[0] == "2:14 unknown-coastline-option");
}
