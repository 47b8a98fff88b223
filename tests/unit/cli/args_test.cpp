// Command-line parsing, and the exit statuses of the built stereomesh binary.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/args.h"
#include "io/output_format.h"
#include "run_binary.h"
#include "scratch_dir.h"

using sm::cli::parse_args;

TEST_CASE("cli: Gmsh flags") {
  auto r = parse_args({"-0", "a.geo", "-setnumber", "n", "3", "-setstring", "s", "x", "-clmin", "0.5",
                       "-clmax", "1e3", "-clscale", "2", "-algo", "del2d", "-format", "msh22", "-bin",
                       "-nt", "2", "-v", "3", "-o", "out.msh", "-I", "lib", "-Iother", "b.geo"});
  REQUIRE(r.ok);
  CHECK(r.args.files == std::vector<std::string>{"a.geo", "b.geo"});
  CHECK(r.args.mesh_dim == 0);
  CHECK(r.args.output == "out.msh");
  REQUIRE(r.args.set_numbers.size() == 1);
  CHECK(r.args.set_numbers[0].second == 3);
  CHECK(r.args.set_strings.at(0).second == "x");
  CHECK(r.args.include_dirs == std::vector<std::string>{"lib", "other"});
  bool algo = false, version = false, clmax = false;
  for (const auto& [name, v] : r.args.option_numbers) {
    if (name == "Mesh.Algorithm") algo = v == 5;
    if (name == "Mesh.MshFileVersion") version = v == 2.2;
    if (name == "Mesh.MeshSizeMax") clmax = v == 1000;
  }
  CHECK(algo);
  CHECK(version);
  CHECK(clmax);
}

TEST_CASE("cli: usage errors") {
  CHECK_FALSE(parse_args({}).ok);
  CHECK_FALSE(parse_args({"-frobnicate", "a.geo"}).ok);
  CHECK_FALSE(parse_args({"a.geo", "-clmax"}).ok);
  CHECK_FALSE(parse_args({"a.geo", "-clmax", "1e3x"}).ok);
  CHECK_FALSE(parse_args({"a.geo", "-clmax", "nan"}).ok);
  CHECK_FALSE(parse_args({"a.geo", "-setnumber", "n"}).ok);
  CHECK_FALSE(parse_args({"a.geo", "-setnumber", "n", "abc"}).ok);
  CHECK_FALSE(parse_args({"a.geo", "-algo", "magic"}).ok);
  // Gmsh's algorithms the kernel lacks are refused with the list of those it has.
  for (const char* missing : {"bamg", "pack", "hxt"}) {
    CAPTURE(missing);
    const sm::cli::ParseOutcome c = parse_args({"a.geo", "-algo", missing});
    CHECK_FALSE(c.ok);
    CHECK(c.error.find("meshadapt, auto, initial2d, del2d, front2d and delquad") != std::string::npos);
  }
  for (const auto& [name, number] : std::vector<std::pair<const char*, double>>{
           {"meshadapt", 1}, {"auto", 2}, {"initial2d", 3}, {"del2d", 5}, {"front2d", 6}, {"delquad", 8}}) {
    const sm::cli::ParseOutcome c = parse_args({"a.geo", "-algo", name});
    REQUIRE(c.ok);
    CHECK(c.args.option_numbers.back() == std::pair<std::string, double>{"Mesh.Algorithm", number});
  }
  CHECK_FALSE(parse_args({"a.geo", "-format", "stl"}).ok);
  CHECK_FALSE(parse_args({"a.geo", "-coords", "polar"}).ok);
  CHECK_FALSE(parse_args({"a.geo", "-coords"}).ok);
  {
    const sm::cli::ParseOutcome c = parse_args({"a.geo", "-coords", "stereo"});
    REQUIRE(c.ok);
    REQUIRE(c.args.option_numbers.size() == 1);
    CHECK(c.args.option_numbers[0] == std::pair<std::string, double>{"Mesh.NodeCoordinates", 2});
  }
  CHECK_FALSE(parse_args({"--test"}).ok);
  CHECK(parse_args({"--help"}).ok);
  CHECK(parse_args({"--version"}).ok);
  CHECK(parse_args({"--test", "dir1", "dir2"}).args.files.size() == 2);
}

namespace {

using sm::testing::run_status;


// What the command prints on stderr (stdout dropped).
std::string run_stderr(const std::string& cmd) { return sm::testing::run_output(cmd, "2>&1 >/dev/null"); }

}  // namespace

TEST_CASE("cli: exit statuses of the binary") {
  const std::string bin = sm::testing::stereomesh_binary();
  if (bin.empty()) {
    MESSAGE("skipped: stereomesh binary not built");
    return;
  }
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_cli_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "ok.geo") << "DefineConstant[n = 1];\nPrintf(\"%g\", n);\n";
  std::ofstream(dir / "bad.geo") << "x = y;\n";
  std::ofstream(dir / "syntax.geo") << "x = (1 + ;\n";
  std::ofstream(dir / "exit.geo") << "Exit 4;\n";
  const std::string d = dir.string() + "/";
  CHECK(run_status(bin + " -0 " + d + "ok.geo") == 0);
  CHECK(run_status(bin + " -0 " + d + "bad.geo") == 1);
  CHECK(run_status(bin + " -0 " + d + "syntax.geo") == 1);
  CHECK(run_status(bin + " -0 " + d + "missing.geo") == 1);
  CHECK(run_status(bin + " -0 " + d + "exit.geo") == 4);
  // -2 meshes and writes (an empty model gives an empty mesh, as Gmsh); a
  // square gives triangles, statistics as JSON, and a picture.
  CHECK(run_status(bin + " -2 " + d + "ok.geo -o " + d + "empty.msh") == 0);
  CHECK(fs::exists(dir / "empty.msh"));
  std::ofstream(dir / "square.geo") << "Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};\n"
                                       "Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};\n"
                                       "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                                       "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n";
  CHECK(run_status(bin + " -2 -v 0 " + d + "square.geo -o " + d + "square.msh --stats " + d + "s.json") == 0);
  {
    std::ifstream msh(dir / "square.msh"), json(dir / "s.json");
    std::stringstream m, j;
    m << msh.rdbuf();
    j << json.rdbuf();
    CHECK(m.str().rfind("$MeshFormat\n4.1 0 8\n", 0) == 0);
    CHECK(m.str().find("$Elements") != std::string::npos);
    CHECK(j.str().find("\"triangles\": ") != std::string::npos);
  }
  CHECK(run_status(bin + " -2 -v 0 " + d + "square.geo -o " + d + "square.svg") == 0);
  CHECK(fs::file_size(dir / "square.svg") > 1000);
  // Progress: nothing on stderr with -v 0 (or up to -v 3) for a clean script;
  // plain lines, no \r, when stderr is not a terminal (here a pipe, as in CI and logs).
  CHECK(run_stderr(bin + " -2 -v 0 " + d + "square.geo -o " + d + "q.msh") == "");
  CHECK(run_stderr(bin + " -2 -v 3 " + d + "square.geo -o " + d + "q.msh") == "");
  {
    const std::string log = run_stderr(bin + " -2 " + d + "square.geo -o " + d + "q.msh");
    CHECK(log.rfind("stereomesh: 1D: start (4)\nstereomesh: 1D: done in ", 0) == 0);
    CHECK(log.find("stereomesh: 2D: start (") != std::string::npos);   // its units are mesh2d's (faces, parts)
    CHECK(log.find("stereomesh: 2D: done in ") != std::string::npos);
    CHECK(log.find('\r') == std::string::npos);
  }
  // On a terminal (a pseudo-terminal from util-linux's script, when there is one): the
  // live line, redrawn with \r and finished with a newline.
  if (run_status("script -qc true /dev/null") == 0) {
    REQUIRE(std::system(("script -qc '" + bin + " -2 " + d + "square.geo -o " + d + "q.msh' /dev/null > " + d +
                         "tty.txt 2>&1 </dev/null").c_str()) == 0);
    std::ifstream in(dir / "tty.txt", std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string tty = ss.str();
    CHECK(tty.find("\r1D  4/4  100%") != std::string::npos);
    CHECK(tty.find("\r2D  ") != std::string::npos);
    CHECK(tty.find("stereomesh: 1D: start") == std::string::npos);
  }
  // PNG by extension and by -format (the default name is the script's with .png).
  CHECK(run_status(bin + " -2 -v 0 " + d + "square.geo -o " + d + "sq.png") == 0);
  CHECK(run_status(bin + " -2 -v 0 -format png " + d + "square.geo") == 0);
  for (const char* png : {"sq.png", "square.png"}) {
    std::ifstream in(dir / png, std::ios::binary);
    std::string head(8, '\0');
    in.read(head.data(), 8);
    CHECK(head == std::string("\x89PNG\r\n\x1a\n", 8));
  }
  // A failed write says so once, naming the file and the reason.
  CHECK(run_stderr(bin + " -2 -v 0 " + d + "square.geo -o " + d + "no/dir/x.msh") ==
        "stereomesh: error: cannot write '" + d + "no/dir/x.msh': No such file or directory [file-write-error]\n");
  CHECK(run_stderr(bin + " -2 -v 0 " + d + "square.geo -o " + d + "x.msh --stats " + d + "no/s.json") ==
        "stereomesh: error: cannot write '" + d + "no/s.json': No such file or directory\n");
  CHECK(run_stderr(bin + " -2 -v 0 " + d + "square.geo -o " + d + "noext") ==
        "stereomesh: error: cannot write '" + d + "noext': the file name has no extension (use .msh, .vtk, .svg, "
        ".png, .14, .gr3 or .nc) [file-write-error]\n");
  // Lon/lat node coordinates of a planar model: a clear error, no file.
  CHECK(run_stderr(bin + " -2 -v 0 -coords lonlat " + d + "square.geo -o " + d + "ll.msh") ==
        "stereomesh: error: cannot write '" + d + "ll.msh': lon/lat node coordinates need a mesh on a sphere "
        "(PolarSphere or Sphere), and this model is planar [file-write-error]\n");
  CHECK_FALSE(fs::exists(dir / "ll.msh"));
  CHECK(run_status(bin + " -2 -v 0 -coords stereo " + d + "square.geo -o " + d + "st.msh") == 0);
  // A script error while meshing leaves no output file; --stats without a mesh is an error.
  std::ofstream(dir / "badalgo.geo") << "Mesh.Algorithm = 7;\nPoint(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};\n"
                                        "Point(3) = {0, 1, 0, 0.1}; Line(1) = {1, 2}; Line(2) = {2, 3};\n"
                                        "Line(3) = {3, 1}; Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\n";
  CHECK(run_status(bin + " -2 -v 0 " + d + "badalgo.geo -o " + d + "badalgo.msh") == 1);
  CHECK_FALSE(fs::exists(dir / "badalgo.msh"));
  // --stats after -1 holds the 1D figures (a plane: model units); with -0 there is no mesh.
  CHECK(run_status(bin + " -1 -v 0 " + d + "square.geo -o " + d + "sq1.msh --stats " + d + "s1.json") == 0);
  CHECK(sm::testing::read_all(dir / "s1.json").find("\"line_elements\": ") != std::string::npos);
  CHECK(sm::testing::read_all(dir / "s1.json").find("\"edge_units\": \"model\"") != std::string::npos);
  CHECK(run_status(bin + " -0 -v 0 " + d + "square.geo --stats " + d + "s0.json") == 1);
  CHECK_FALSE(fs::exists(dir / "s0.json"));
  CHECK(run_status(bin + " --bogus " + d + "ok.geo") == 2);
  CHECK(run_status(bin + " -0 -setnumber Mesh.Algoritm 5 " + d + "ok.geo") == 2);
  CHECK(run_status(bin + " --test " + d + "nowhere") == 2);
  // Include finds files through -I and $STEREOMESH_PATH (after the script's directory).
  fs::create_directories(dir / "lib1");
  fs::create_directories(dir / "lib2");
  std::ofstream(dir / "lib1" / "one.geo") << "one = 1;\n";
  std::ofstream(dir / "lib2" / "two.geo") << "two = 2;\n";
  std::ofstream(dir / "inc.geo") << "Include \"one.geo\";\nInclude \"two.geo\";\nAssert(one + two == 3);\n";
  CHECK(run_status(bin + " -0 " + d + "inc.geo") == 1);
  CHECK(run_status("STEREOMESH_PATH=/nonexistent:" + d + "lib2 " + bin + " -0 -I " + d + "lib1 " + d + "inc.geo") == 0);
  // Printf on stdout, diagnostics on stderr.
  std::FILE* p = ::popen((bin + " -0 -setnumber n 7 " + d + "ok.geo 2>/dev/null").c_str(), "r");
  REQUIRE(p);
  char buf[64] = {};
  const std::size_t n = std::fread(buf, 1, sizeof buf - 1, p);
  ::pclose(p);
  CHECK(std::string(buf, n) == "7\n");
  fs::remove_all(dir);
}

TEST_CASE("cli: -part N is Mesh.NbPartitions, a whole number from 1") {
  const sm::cli::ParseOutcome c = parse_args({"a.geo", "-part", "4"});
  REQUIRE(c.ok);
  CHECK(c.args.option_numbers.back() == std::pair<std::string, double>{"Mesh.NbPartitions", 4});
  for (const char* bad : {"0", "-1", "2.5", "four", "1e9"}) {
    CAPTURE(bad);
    const sm::cli::ParseOutcome b = parse_args({"a.geo", "-part", bad});
    CHECK_FALSE(b.ok);
    CHECK(b.error.find("'-part' needs a whole number of partitions, 1 or more") != std::string::npos);
  }
  CHECK_FALSE(parse_args({"a.geo", "-part"}).ok);
}

TEST_CASE("cli: partitions asked for in a format without them are refused before meshing") {
  const std::string bin = sm::testing::stereomesh_binary();
  if (bin.empty()) {
    MESSAGE("skipped: stereomesh binary not built");
    return;
  }
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_cli_part_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "sq.geo") << "Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2};\n"
                                   "Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};\n"
                                   "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                                   "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n";
  const std::string geo = (dir / "sq.geo").string();
  for (const std::string out : {"sq.14", "sq.svg", "sq.png", "sq.gr3"}) {
    CAPTURE(out);
    const std::string cmd = bin + " -2 -part 2 " + geo + " -o " + (dir / out).string();
    const std::string err = run_stderr(cmd);
    CHECK(err.find("cannot hold the 2 partitions") != std::string::npos);
    CHECK(err.find("[partitions-not-held]") != std::string::npos);
    CHECK(err.find("2D: start") == std::string::npos);   // said before meshing
    CHECK(run_status(cmd) == 1);
    CHECK_FALSE(fs::exists(dir / out));
  }
  CHECK(run_status(bin + " -2 -v 0 -part 2 -format msh22 " + geo + " -o " + (dir / "sq2.msh").string()) == 1);
  CHECK(run_status(bin + " -2 -v 0 -part 2 -setnumber Mesh.MshFileVersion 2.2 " + geo + " -o " +
                   (dir / "sq2.msh").string()) == 1);
  CHECK_FALSE(fs::exists(dir / "sq2.msh"));
  // More parts than triangles: after meshing, nothing written.
  const std::string many = bin + " -2 -part 100000 " + geo + " -o " + (dir / "many.msh").string();
  CHECK(run_stderr(many).find("100000 partitions of ") != std::string::npos);
  CHECK(run_status(many) == 1);
  CHECK_FALSE(fs::exists(dir / "many.msh"));
  // The formats that hold them.
  for (const std::string out : {"sq.msh", "sq.vtk", "sq.nc"}) {
    CAPTURE(out);
    CHECK(run_status(bin + " -2 -v 0 -part 3 " + geo + " -o " + (dir / out).string()) == 0);
    CHECK(fs::exists(dir / out));
  }
  // One file per part, named as Gmsh names them, and not the file itself.
  CHECK(run_status(bin + " -2 -v 0 -part 3 -setnumber Mesh.PartitionSplitMeshFiles 1 " + geo + " -o " +
                   (dir / "split.msh").string()) == 0);
  for (const char* f : {"split_1.msh", "split_2.msh", "split_3.msh"}) CHECK(fs::exists(dir / f));
  CHECK_FALSE(fs::exists(dir / "split.msh"));
  fs::remove_all(dir);
}

TEST_CASE("cli: running out of memory while meshing is a located script error, not a crash") {
  const std::string bin = sm::testing::stereomesh_binary();
  if (bin.empty()) {
    MESSAGE("skipped: stereomesh binary not built");
    return;
  }
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_cli_oom_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // 1e9 nodes on one line, within a budget raised to 1e15: placing them needs 8 GB, more
  // than the 2 GB of address space the shell allows the process.
  std::ofstream(dir / "oom.geo") << "Point(1) = {0, 0, 0, 1e-9}; Point(2) = {1, 0, 0, 1e-9}; Line(1) = {1, 2};\n"
                                    "Mesh.MaxElements = 1e15;\nMesh 1;\nSave \"oom.msh\";\n";
  const std::string cmd = "ulimit -v 2000000; " + bin + " -0 " + (dir / "oom.geo").string();
  CHECK(run_status("sh -c '" + cmd + "'") == 1);
  const std::string err = run_stderr("sh -c '" + cmd + "'");
  CHECK(err.find("oom.geo:3:1: error: out of memory while meshing in 1D") != std::string::npos);
  CHECK(err.find("[out-of-memory]") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "oom.msh"));
  fs::remove_all(dir);
}

TEST_CASE("cli: -format and --help follow io/output_format.h's table") {
  const std::string usage = sm::cli::usage_text();
  const std::size_t line = usage.find("  -format NAME        ");
  REQUIRE(line != std::string::npos);
  const std::string section = usage.substr(line, usage.find("  -bin", line) - line);
  for (const sm::io::OutputFormat& f : sm::io::output_formats()) {
    CAPTURE(f.name);
    CHECK(section.find(std::string(f.name)) != std::string::npos);
    const sm::cli::ParseOutcome c = parse_args({"a.geo", "-format", std::string(f.name)});
    REQUIRE(c.ok);
    CHECK(c.args.format == f.name);
    std::vector<std::pair<std::string, double>> expected;
    if (f.mesh_format != 0) expected.emplace_back("Mesh.Format", f.mesh_format);
    if (f.msh_file_version != 0) expected.emplace_back("Mesh.MshFileVersion", f.msh_file_version);
    CHECK(c.args.option_numbers == expected);
  }
  const sm::cli::ParseOutcome bad = parse_args({"a.geo", "-format", "stl"});
  REQUIRE_FALSE(bad.ok);
  CHECK(bad.error == "unknown format 'stl' (" + sm::io::output_format_names() + ")");
}
