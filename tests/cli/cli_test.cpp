// Drives the command line as a user would: exit codes, messages and the
// files a run leaves behind.
#include <gtest/gtest.h>
#include <png.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <thread>

#include "rift/io/read_mesh.hpp"

namespace {

namespace fs = std::filesystem;

// A frame file is whole: its XML part parses and it ends with its closing tag
// (the appended binary data after <AppendedData> is not XML).
bool frame_is_complete(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t cut = text.find("<AppendedData");
  const std::string xml = cut == std::string::npos ? text : text.substr(0, cut) + "</VTKFile>";
  pugi::xml_document doc;
  return doc.load_string(xml.c_str()) && text.ends_with("</VTKFile>\n");
}

struct Result {
  int code;
  std::string output;  // stdout and stderr
};

Result run(const std::string& exe, const std::string& args) {
  const std::string cmd = "'" + exe + "' " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf{};
  while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe))
    out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

Result sim(const std::string& args) {
  return run(RIFT_TEST_SIM, args);
}

void expect_no_temporary_files(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
}

/// Every frame the PVD lists parses; returns how many.
int readable_frames(const fs::path& dir, const std::string& name) {
  pugi::xml_document pvd;
  if (!pvd.load_file((dir / (name + ".pvd")).c_str())) return -1;
  int frames = 0;
  for (pugi::xml_node ds : pvd.child("VTKFile").child("Collection").children("DataSet")) {
    if (!frame_is_complete(dir / ds.attribute("file").value())) return -1;
    ++frames;
  }
  return frames;
}

/// Column `column` of every row of a CSV written by rift run.
std::vector<double> csv_column(const fs::path& file, int column) {
  std::ifstream in(file);
  std::vector<double> values;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (int c = 0; c <= column; ++c)
      std::getline(row, cell, ',');
    values.push_back(std::stod(cell));
  }
  return values;
}

/// A CSV written by rift run without its timing column (step_ms, found by
/// name in the header): what must not change between two runs.
std::string drop_timing_column(const std::string& csv) {
  std::stringstream in(csv);
  std::string line, out;
  int timing = -1;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');)
      cells.push_back(cell);
    if (timing < 0) {
      for (std::size_t k = 0; k < cells.size(); ++k) {
        if (cells[k] == "step_ms") timing = static_cast<int>(k);
      }
    }
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (static_cast<int>(k) != timing) out += cells[k] + ",";
    }
    out += "\n";
  }
  return out;
}

/// Compares every file of two output folders byte for byte (CSV without
/// its timing column); returns how many were compared.
int expect_same_outputs(const fs::path& a_dir, const fs::path& b_dir, const std::string& what) {
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(a_dir)) {
    const fs::path name = entry.path().filename();
    EXPECT_TRUE(fs::exists(b_dir / name)) << what << ": " << name;
    std::ifstream fa(entry.path(), std::ios::binary), fb(b_dir / name, std::ios::binary);
    std::string a((std::istreambuf_iterator<char>(fa)), std::istreambuf_iterator<char>());
    std::string b((std::istreambuf_iterator<char>(fb)), std::istreambuf_iterator<char>());
    if (name.extension() == ".csv") {
      EXPECT_NE(a.find("step_ms"), std::string::npos) << "the timing column moved: " << name;
      a = drop_timing_column(a);
      b = drop_timing_column(b);
    }
    EXPECT_EQ(a, b) << what << ": " << name << " differs";
    ++compared;
  }
  return compared;
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("rift_cli_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
};

const char* kCloth = R"([mesh]
source = "grid:quad:6x6"
rotate = [90, 0, 0]

[simulation]
integrator = "rk4"
dt = 0.001
steps = 60

[mass]
total = 0.1

[pin]
corners = ["top-left", "top-right"]

[[interaction]]
name = "test_springs"
stiffness = 60
damping = 0.1

[output]
every = 20
formats = ["vtu", "png", "csv"]
png_size = [320, 240]
)";

TEST_F(Cli, VersionAndHelp) {
  Result r = sim("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.output.find("rift 0.1.0"), std::string::npos);
  r = sim("--help");
  EXPECT_EQ(r.code, 0);
  for (const char* cmd : {"run", "bench", "info", "list"}) {
    EXPECT_NE(r.output.find(cmd), std::string::npos) << cmd;
  }
  r = sim("frobnicate");
  EXPECT_NE(r.code, 0);
  r = sim("info --help");
  EXPECT_NE(r.output.find("grid:quad:NxM"), std::string::npos);
}

TEST_F(Cli, InfoLineAndJson) {
  Result r = sim("info grid:quad:10x10");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.output,
            "dimension=2 darts=800 vertices=121 edges=220 faces=100 volumes=0 components=1 "
            "boundary_edges=40\n");
  r = sim("info block:hex:2x2x2 --json");
  ASSERT_EQ(r.code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  for (const char* key :
       {"darts", "vertices", "edges", "faces", "volumes", "components", "boundary_faces"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["volumes"], 8);
  r = sim("info " + (dir_ / "missing.obj").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("missing.obj: error: no such file"), std::string::npos) << r.output;
  r = sim("info grid:quad:0x3");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("at least 1"), std::string::npos) << r.output;
}

TEST_F(Cli, ListShowsComponentsAndParameters) {
  Result r = sim("list");
  EXPECT_EQ(r.code, 0);
  for (const char* text : {"pack test2d (2D)", "test_springs", "stiffness : real (required)",
                           "damping : real = 0", "test_long_edge", "limit"}) {
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
  }
}

// A pack that imports another (criteria2d imports topology2d) applies its
// rules without copying them: `rift list` shows each rule under the one pack
// that declares it.
TEST_F(Cli, RiftListsEveryRuleOnceUnderItsPack) {
  const Result r = run(RIFT_EXE, "list");
  ASSERT_EQ(r.code, 0) << r.output;
  // A 2D and a 3D pack may both have a `split_vertex`: rules are keyed by
  // name and dimension, as a scene of one dimension finds them.
  std::map<std::string, std::string> pack_of;  // "rule (2D)" -> pack
  std::string pack, dimension;
  bool in_rules = false;
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("pack ", 0) == 0) {
      const std::size_t space = line.find(' ', 5);
      pack = line.substr(5, space - 5);
      dimension = line.substr(space + 1, line.find(')', space) - space);
      in_rules = false;
    } else if (line == "  rules:") {
      in_rules = true;
    } else if (line.rfind("  ", 0) == 0 && line.rfind("    ", 0) != 0) {
      in_rules = false;  // the next section of the pack
    } else if (in_rules && line.rfind("    ", 0) == 0) {
      const std::string rule = line.substr(4) + " " + dimension;
      const auto [it, fresh] = pack_of.emplace(rule, pack);
      EXPECT_TRUE(fresh) << "rule '" << rule << "' is listed under '" << it->second << "' and '"
                         << pack << "'";
    }
  }
  EXPECT_EQ(pack_of["separate_faces (2D)"], "topology2d") << r.output;
  EXPECT_EQ(pack_of["split_vertex (3D)"], "topology3d") << r.output;
  EXPECT_EQ(pack_of["separate_volumes (3D)"], "topology3d") << r.output;
  EXPECT_EQ(pack_of["split_along_largest_force (2D)"], "criteria2d") << r.output;
}

TEST_F(Cli, RunWritesReadableFrames) {
  const std::string scene = write("cloth.toml", kCloth);
  const fs::path out = dir_ / "out";
  Result r = sim("run " + scene + " --out " + out.string() + " --quiet");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output, "");  // --quiet and no progress bar when piped

  // The PVD lists every frame, and every frame parses with its points.
  pugi::xml_document pvd;
  ASSERT_TRUE(pvd.load_file((out / "cloth.pvd").c_str()));
  int frames = 0;
  for (pugi::xml_node ds : pvd.child("VTKFile").child("Collection").children("DataSet")) {
    // Frames are appended binary VTU: rift's own reader reads them back.
    const fs::path file = out / ds.attribute("file").value();
    const rift::MeshData frame = rift::read_mesh_file(file.string());
    EXPECT_EQ(frame.points.size(), 49u);
    EXPECT_EQ(frame.elements.size(), 36u);
    ++frames;
  }
  EXPECT_EQ(frames, 4);  // steps 0, 20, 40, 60

  // CSV: a header naming the columns, one row per frame.
  std::ifstream csv(out / "cloth.csv");
  std::string header;
  std::getline(csv, header);
  for (const char* col :
       {"time", "kinetic_energy", "potential_energy", "tears", "vertices", "elements", "step_ms"}) {
    EXPECT_NE(header.find(col), std::string::npos) << col;
  }
  int rows = 0;
  for (std::string line; std::getline(csv, line);)
    ++rows;
  EXPECT_EQ(rows, 4);

  // PNG: signature and size.
  const fs::path png = out / "frame_000000.png";
  ASSERT_TRUE(fs::exists(png));
  std::ifstream in(png, std::ios::binary);
  std::array<unsigned char, 24> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  EXPECT_EQ(png_sig_cmp(head.data(), 0, 8), 0);
  auto be32 = [&](int at) {
    return (head[at] << 24) | (head[at + 1] << 16) | (head[at + 2] << 8) | head[at + 3];
  };
  EXPECT_EQ(be32(16), 320);
  EXPECT_EQ(be32(20), 240);
}

TEST_F(Cli, TearingRunCountsTears) {
  std::string text = kCloth;
  text.replace(text.find("stiffness = 60"), 14, "stiffness = 3");
  text += "\n[[criterion]]\nname = \"test_long_edge\"\nlimit = 0.18\n";
  text.replace(text.find("steps = 60"), 10, "steps = 300");
  const std::string scene = write("soft.toml", text);
  Result r = sim("run " + scene + " --out " + (dir_ / "o").string() + " --check");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("done: 300 steps"), std::string::npos) << r.output;
  std::ifstream csv(dir_ / "o" / "soft.csv");
  std::string line, last;
  std::getline(csv, line);
  const auto cols = line;
  while (std::getline(csv, line))
    last = line;
  // "tears" is the fifth column.
  std::stringstream ss(last);
  std::string cell;
  for (int k = 0; k < 5; ++k)
    std::getline(ss, cell, ',');
  EXPECT_GT(std::stod(cell), 0) << cols << "\n" << last;
}

TEST_F(Cli, BenchJson) {
  const std::string scene = write("cloth.toml", kCloth);
  Result r = sim("bench " + scene + " --steps 30 --json");
  ASSERT_EQ(r.code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_GT(j["ns_per_step"].get<double>(), 0);
  EXPECT_EQ(j["steps"], 30);
  EXPECT_EQ(j["tears"], 0);
  EXPECT_EQ(j["vertices"], 49);
  EXPECT_NEAR(j["ns_per_vertex"].get<double>(), j["ns_per_step"].get<double>() / 49, 0.01);
  // Set-up time and the process's peak RSS (issue 12): present and plausible.
  EXPECT_GT(j["setup_ms"].get<double>(), 0);
  EXPECT_GT(j["peak_rss_mb"].get<double>(), 1);
  EXPECT_LT(j["peak_rss_mb"].get<double>(), 1e5);
  // The set-up's phases, in order, within the set-up's time, each with the
  // resident memory when it ended.
  std::vector<std::string> names;
  double sum = 0;
  for (const auto& p : j["setup_phases"]) {
    names.push_back(p["name"].get<std::string>());
    EXPECT_GE(p["ms"].get<double>(), 0) << names.back();
    EXPECT_GT(p["rss_mb"].get<double>(), 1) << names.back();
    sum += p["ms"].get<double>();
  }
  // The test pack's interaction is named by its kernel.
  ASSERT_EQ(names.size(), 10u);
  EXPECT_EQ(names[6].rfind("interaction test_", 0), 0u) << names[6];
  names[6] = "interaction";
  const std::vector<std::string> expected = {
      "mesh",          "assembly",    "pack inits", "masses",     "notches, handles, loads",
      "vertex masses", "interaction", "criteria",   "integrator", "checks"};
  EXPECT_EQ(names, expected);
  // They cover the set-up from its start to its end (this scene's set-up
  // takes a fraction of a millisecond: an absolute margin for rounding and
  // the timers' own reads).
  EXPECT_LE(sum, j["setup_ms"].get<double>() + 0.01);
  EXPECT_GT(sum, 0.5 * j["setup_ms"].get<double>() - 0.05);
  // The arrays held after the last step, largest first, adding up to
  // memory_mb (Simulation::report_memory; exact counts: MemoryReport.*).
  double held = 0, previous = 1e300;
  bool map_links = false;
  for (const auto& m : j["memory"]) {
    const double mb = m["mb"].get<double>();
    EXPECT_LE(mb, previous);
    previous = mb;
    held += mb;
    map_links |= m["owner"] == "map" && m["what"] == "alpha0 links";
  }
  EXPECT_TRUE(map_links);
  EXPECT_GT(j["memory_mb"].get<double>(), 0);
  EXPECT_NEAR(held, j["memory_mb"].get<double>(), 0.01 + 0.001 * held);
}

TEST_F(Cli, BadScenesExitWithFileLineAndReason) {
  auto expect_error = [&](const std::string& from, const std::string& to, const std::string& msg) {
    std::string text = kCloth;
    text.replace(text.find(from), from.size(), to);
    const std::string scene = write("bad.toml", text);
    Result r = sim("run " + scene + " --out " + (dir_ / "o").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find(scene + msg), std::string::npos) << r.output;
  };
  expect_error("steps = 60", "stepz = 60",
               ":8: error: unknown key 'stepz' in [simulation] (did you mean 'steps'?)");
  expect_error("dt = 0.001", "dt = -1", ":7: error: 'dt' must be positive, not -1");
  expect_error("\"grid:quad:6x6\"", "\"nowhere.msh\"", ":2: error: mesh file");
  expect_error("stiffness = 60", "stiffness = \"stiff\"",
               ":18: error: 'stiffness' must be a number, not a string");
  expect_error("total = 0.1", "total = -0.1", ":11: error: 'total' must be positive");
  expect_error("\"test_springs\"", "\"test_spring\"",
               ":17: error: unknown interaction 'test_spring' (did you mean 'test_springs'?)");
  Result r = sim("run " + (dir_ / "none.toml").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("none.toml: error: no such scene file"), std::string::npos);
}

TEST_F(Cli, ExplosionStopsAndKeepsFramesReadable) {
  std::string text = kCloth;
  text.replace(text.find("dt = 0.001"), 10, "dt = 0.05");
  text.replace(text.find("integrator = \"rk4\""), 18, "integrator = \"euler\"");
  text.replace(text.find("steps = 60"), 10, "steps = 5000");
  text.replace(text.find("every = 20"), 10, "every = 1");
  text.replace(text.find("stiffness = 60"), 14, "stiffness = 6000");
  const std::string scene = write("boom.toml", text);
  Result r = sim("run " + scene + " --out " + (dir_ / "o").string() + " --quiet");
  EXPECT_EQ(r.code, 1) << r.output;
  // Caught by the energy bound long before a value becomes non-finite.
  EXPECT_NE(r.output.find("diverged at step"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("of element"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("dt = 0.0125"), std::string::npos) << r.output;
  pugi::xml_document pvd;
  ASSERT_TRUE(pvd.load_file((dir_ / "o" / "boom.pvd").c_str()));
  int frames = 0;
  for (pugi::xml_node ds : pvd.child("VTKFile").child("Collection").children("DataSet")) {
    EXPECT_TRUE(frame_is_complete(dir_ / "o" / ds.attribute("file").value()));
    ++frames;
  }
  EXPECT_GE(frames, 1);
}

TEST_F(Cli, CtrlCFinishesTheFrameAndClosesTheFiles) {
  std::string text = kCloth;
  text.replace(text.find("steps = 60"), 10, "steps = 100000000");
  text.replace(text.find("every = 20"), 10, "every = 50");
  const std::string scene = write("long.toml", text);
  const std::string out = (dir_ / "o").string();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    execl(RIFT_TEST_SIM, RIFT_TEST_SIM, "run", scene.c_str(), "--out", out.c_str(), "--quiet",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Wait until a few frames exist, then interrupt.
  for (int k = 0; k < 200 && !fs::exists(dir_ / "o" / "frame_000003.vtu"); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  pugi::xml_document pvd;
  ASSERT_TRUE(pvd.load_file((dir_ / "o" / "long.pvd").c_str()));
  int frames = 0;
  for (pugi::xml_node ds : pvd.child("VTKFile").child("Collection").children("DataSet")) {
    EXPECT_TRUE(frame_is_complete(dir_ / "o" / ds.attribute("file").value()));
    ++frames;
  }
  EXPECT_GE(frames, 4);
  expect_no_temporary_files(dir_ / "o");
  // The CSV has a row for every frame, the last one included.
  std::ifstream csv(dir_ / "o" / "long.csv");
  int rows = -1;
  for (std::string line; std::getline(csv, line);)
    ++rows;
  EXPECT_EQ(rows, frames);
}

TEST_F(Cli, RiftWithoutPacksExplains) {
  const std::string scene = write("cloth.toml", kCloth);
  Result r = run(RIFT_EXE, "run " + scene);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("unknown interaction 'test_springs'"), std::string::npos) << r.output;
}

// Issue 13's first case: a co-rotational beam (block:tet:8x8x50 over the unit
// cube, E = 1 MPa, 1 kg) stepped with RK4 at dt = 1e-4 s. Unchecked, its
// kinetic energy passes 1e15 J at step 5; checked, the run stops at step 3
// (3.4e4 J against a bound of 1.7e3 J) and keeps frames 0-2.
const char* kStiffBeam = R"([mesh]
source = "block:tet:8x8x50"

[simulation]
integrator = "rk4"
dt = 0.0001
steps = 50
gravity = [0, 0, -9.81]

[mass]
total = 1.0

[pin]
box = { min = [-1, -1, -0.001], max = [2, 2, 0.001] }

[[interaction]]
name = "corotational"
young = 1.0e6
poisson = 0.3

[output]
every = 1
formats = ["vtu", "csv"]
)";

TEST_F(Cli, StiffBeamWithRk4StopsAtTheFirstStepPastTheBound) {
  const std::string scene = write("beam.toml", kStiffBeam);
  Result r = run(RIFT_EXE, "run " + scene + " --out " + (dir_ / "o").string() + " --quiet");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("diverged at step 3 (t = 0.0003 s)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("of element"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("dt = 2.5e-05"), std::string::npos) << r.output;
  EXPECT_EQ(readable_frames(dir_ / "o", "beam"), 3);
  expect_no_temporary_files(dir_ / "o");
  // The energies before the stop stayed small: stopped early, not at overflow.
  const std::vector<double> energy = csv_column(dir_ / "o" / "beam.csv", 2);
  ASSERT_EQ(energy.size(), 3u);
  EXPECT_LT(energy.back(), 1.0);

  // Without the check (divergence_factor = 0) the same run explodes on.
  std::string text = kStiffBeam;
  text.replace(text.find("steps = 50"), 10, "steps = 5\ndivergence_factor = 0");
  text.replace(text.find("formats = [\"vtu\", \"csv\"]"), 24, "formats = [\"csv\"]");
  r = run(RIFT_EXE,
          "run " + write("beam0.toml", text) + " --out " + (dir_ / "u").string() + " --quiet");
  EXPECT_EQ(r.code, 0) << r.output;
  const std::vector<double> unchecked = csv_column(dir_ / "u" / "beam0.csv", 2);
  ASSERT_EQ(unchecked.size(), 6u);
  EXPECT_GT(unchecked[5], 1e12);
}

// Issue 13's second case: a 30 x 30 cloth torn at every vertex whose force
// sum passes 1 mN; split vertices are light and RK4 with the damping passes
// its limit. Unchecked it reaches 1e200 J by step 50 and ends "done".
const char* kTornCloth = R"([mesh]
source = "grid:quad:30x30"
rotate = [90, 0, 0]

[simulation]
integrator = "rk4"
dt = 0.0005
steps = 50
gravity = [0, 0, -9.81]

[mass]
total = 0.1

[pin]
corners = ["top-left", "top-right"]

[[interaction]]
name = "stretch"
stiffness = 60.0
damping = 0.1

[[interaction]]
name = "shear"
stiffness = 43.0
damping = 0.1

[[interaction]]
name = "bend"
stiffness = 10.0
damping = 0.1

[[criterion]]
name = "vertex_sum"
threshold = 0.001

[output]
every = 1
formats = ["vtu", "csv"]
)";

TEST_F(Cli, HeavilyTornClothStopsWhenTheEnergyPassesTheBound) {
  Result r = run(RIFT_EXE, "run " + write("torn.toml", kTornCloth) + " --out " +
                               (dir_ / "o").string() + " --quiet");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("diverged at step 5 "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("the most energetic is vertex"), std::string::npos) << r.output;
  EXPECT_EQ(readable_frames(dir_ / "o", "torn"), 5);
  expect_no_temporary_files(dir_ / "o");

  std::string text = kTornCloth;
  text.replace(text.find("steps = 50"), 10, "steps = 50\ndivergence_factor = 0");
  text.replace(text.find("formats = [\"vtu\", \"csv\"]"), 24, "formats = [\"csv\"]");
  r = run(RIFT_EXE, "run " + write("torn0.toml", text) + " --out " + (dir_ / "u").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("done: 50 steps"), std::string::npos) << r.output;
  const std::vector<double> unchecked = csv_column(dir_ / "u" / "torn0.csv", 2);
  ASSERT_EQ(unchecked.size(), 51u);
  EXPECT_GT(unchecked.back(), 1e100);
}

// A long step: a 300,000-gon with the test pack's face walk (each of its
// vertices walks the whole face: minutes a step). Ctrl-C one second into the
// first step stops it part-way, with the first frame intact and no
// temporary file.
TEST_F(Cli, CtrlCInsideALongStepStopsAtOnce) {
  {
    std::ofstream obj(dir_ / "polygon.obj");
    const int n = 300000;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * 3.141592653589793 * i / n;
      obj << "v " << std::cos(a) << " " << std::sin(a) << " 0\n";
    }
    obj << "f";
    for (int i = 1; i <= n; ++i)
      obj << " " << i;
    obj << "\n";
  }
  const std::string scene = write("polygon.toml", R"([mesh]
source = "polygon.obj"

[simulation]
steps = 3

[mass]
total = 0.1

[[interaction]]
name = "test_springs"
stiffness = 60.0

[[criterion]]
name = "test_face_walk"

[output]
every = 1
formats = ["vtu", "csv"]
)");
  const std::string out = (dir_ / "o").string();
  const std::string log = (dir_ / "log.txt").string();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (!std::freopen(log.c_str(), "w", stderr)) _exit(126);
    execl(RIFT_TEST_SIM, RIFT_TEST_SIM, "run", scene.c_str(), "--out", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // The first frame is written just before the first step starts (its files
  // appear by rename once complete; a frame of 300,000 vertices takes a while).
  const auto first_frame_written = [&] {
    return fs::exists(dir_ / "o" / "polygon.pvd") && fs::exists(dir_ / "o" / "polygon.csv") &&
           fs::exists(dir_ / "o" / "frame_000000.vtu");
  };
  for (int k = 0; k < 1200 && !first_frame_written(); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const auto sent = std::chrono::steady_clock::now();
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  const double latency =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  std::cout << "interrupt latency inside a step: " << latency << " s\n";
  std::ifstream in(log);
  const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_TRUE(WIFEXITED(status)) << output;
  EXPECT_EQ(WEXITSTATUS(status), 130) << output;
  EXPECT_NE(output.find("interrupted during step 1"), std::string::npos) << output;
  // The step itself lasts many seconds; polling stops it within a fraction of a
  // second (the bound leaves room for a loaded machine).
  EXPECT_LT(latency, 5.0) << output;
  EXPECT_EQ(readable_frames(dir_ / "o", "polygon"), 1);
  expect_no_temporary_files(dir_ / "o");
}

// Frames are large and written every step: interrupts land while files are
// written, and every file the run leaves is complete.
TEST_F(Cli, CtrlCWhileWritingFramesLeavesNoTemporaryFile) {
  std::string text = kCloth;
  text.replace(text.find("steps = 60"), 10, "steps = 100000");
  text.replace(text.find("every = 20"), 10, "every = 1");
  text.replace(text.find("png_size = [320, 240]"), 21, "png_size = [1600, 1200]");
  const std::string scene = write("frames.toml", text);
  for (int attempt = 0; attempt < 4; ++attempt) {
    fs::path out = dir_ / "o";
    out += std::to_string(attempt);  // (GCC 12 -Wrestrict misfires on "o" + string)
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      execl(RIFT_TEST_SIM, RIFT_TEST_SIM, "run", scene.c_str(), "--out", out.c_str(), "--quiet",
            static_cast<char*>(nullptr));
      _exit(127);
    }
    // Up to a minute for the third frame: sanitizer builds on a loaded
    // machine are slow, and an interrupt before it would test nothing.
    for (int k = 0; k < 6000 && !fs::exists(out / "frame_000002.vtu"); ++k)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (!fs::exists(out / "frame_000002.vtu")) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
    ASSERT_TRUE(fs::exists(out / "frame_000002.vtu")) << "no third frame after a minute";
    std::this_thread::sleep_for(std::chrono::milliseconds(7 * attempt));
    kill(pid, SIGINT);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);
    EXPECT_GE(readable_frames(out, "frames"), 3);
    expect_no_temporary_files(out);
  }
}

// Runs `scene` twice with `args` and expects every output file byte-identical,
// the statistics too once the timing column (step_ms) is dropped; returns the
// number of files compared.
int expect_identical_runs(const fs::path& dir, const std::string& scene, const std::string& args) {
  for (const char* out : {"a", "b"}) {
    const Result r =
        run(RIFT_EXE, "run " + scene + " " + args + " --out " + (dir / out).string() + " --quiet");
    EXPECT_EQ(r.code, 0) << r.output;
  }
  return expect_same_outputs(dir / "a", dir / "b", "second run");
}

// The same tearing scene twice: every frame byte-identical, the statistics
// too once the timing column (step_ms) is dropped.
TEST_F(Cli, TheSameSceneTwiceGivesByteIdenticalOutputs) {
  // Fig. 11 tears at its pins within its first 300 steps.
  const std::string scene = std::string(RIFT_SOURCE_DIR) + "/examples/paper/fig11.toml";
  EXPECT_GE(expect_identical_runs(dir_, scene, "--steps 300"), 10);  // 4 VTU, 4 PNG, PVD, CSV
  const std::vector<double> tears = csv_column(dir_ / "a" / "fig11.csv", 4);
  EXPECT_GT(tears.back(), 0) << "the scene should tear";
}

// Issue 12: every core, the same bits. A tearing cloth (RK4: parallel force
// passes, gathers rebuilt after each tear, parallel sweeps) and an implicit
// beam (parallel Jacobians, products and fixed-block dot products), both
// large enough that every pass has several blocks, run with 1, 2 and 8
// threads: every VTU and CSV (timing column aside) byte-identical.
TEST_F(Cli, AnyThreadCountGivesByteIdenticalOutputs) {
  const std::string cloth = write("cloth.toml", R"([mesh]
source = "grid:quad:80x80"
rotate = [90, 0, 0]

[simulation]
integrator = "rk4"
dt = 0.0005
steps = 100
gravity = [0, 0, -9.81]

[mass]
total = 2.0

[pin]
corners = ["top-left", "top-right"]

[[interaction]]
name = "stretch"
stiffness = 60.0
damping = 0.1

[[interaction]]
name = "shear"
stiffness = 43.0
damping = 0.1

[[interaction]]
name = "bend"
stiffness = 10.0
damping = 0.1

[[criterion]]
name = "atomic_edge"
threshold = 0.2

[output]
every = 25
formats = ["vtu", "csv"]
)");
  const std::string beam = write("beam.toml", R"([mesh]
source = "block:tet:8x8x60"
scale = [0.2, 0.2, 1.0]

[simulation]
integrator = "implicit_euler"
dt = 0.002
steps = 4
gravity = [0, -9.81, 0]

[mass]
total = 1.0

[pin]
box = { min = [-1, -1, -0.001], max = [2, 2, 0.001] }

[[interaction]]
name = "corotational"
young = 1.0e5
poisson = 0.3

[output]
every = 2
formats = ["vtu", "csv"]
)");
  for (const std::string& scene : {cloth, beam}) {
    const std::string name = fs::path(scene).stem().string();
    for (const char* threads : {"1", "2", "8"}) {
      const fs::path out = dir_ / (name + "_" + threads);
      const Result r = run(RIFT_EXE, "run " + scene + " --threads " + threads + " --out " +
                                         out.string() + " --quiet");
      ASSERT_EQ(r.code, 0) << r.output;
    }
    const fs::path one = dir_ / (name + "_1");
    EXPECT_GE(expect_same_outputs(one, dir_ / (name + "_2"), name + ", 2 threads"), 4);
    EXPECT_GE(expect_same_outputs(one, dir_ / (name + "_8"), name + ", 8 threads"), 4);
  }
  const std::vector<double> tears = csv_column(dir_ / "cloth_1" / "cloth.csv", 4);
  EXPECT_GT(tears.back(), 0) << "the cloth should tear";
}

TEST_F(Cli, BadThreadCountsAreRefused) {
  const std::string scene = write("cloth.toml", kCloth);
  for (const char* bad : {"0", "-2", "two", "1.5"}) {
    const Result r = sim("run " + scene + " --threads " + bad + " --out " + (dir_ / "o").string());
    EXPECT_NE(r.code, 0) << bad;
    EXPECT_NE(r.output.find("--threads"), std::string::npos) << bad << ": " << r.output;
  }
  const Result r = sim("bench " + scene + " --steps 3 --threads 2 --json");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("\"threads\": "), std::string::npos) << r.output;
}

// The same in 3D: a co-rotational cantilever of tetrahedra whose vertices
// split under its own weight (vertex_stress), binary VTU frames.
TEST_F(Cli, TheSame3DSceneTwiceGivesByteIdenticalOutputs) {
  const std::string scene = write("beam.toml", R"([mesh]
source = "block:tet:6x2x2"
scale = [0.3, 0.1, 0.1]
[simulation]
integrator = "rk4"
dt = 2e-4
steps = 150
gravity = [0, 0, -9.81]
[mass]
density = 1000.0
[pin]
box = { min = [-0.01, -1, -1], max = [0.01, 1, 1] }
[[interaction]]
name = "corotational"
young = 1.0e4
[[criterion]]
name = "vertex_stress"
threshold = 100.0
[output]
every = 50
formats = ["vtu", "csv"]
)");
  EXPECT_EQ(expect_identical_runs(dir_, scene, ""), 6);  // 4 VTU, PVD, CSV
  const std::vector<double> tears = csv_column(dir_ / "a" / "beam.csv", 4);
  EXPECT_GT(tears.back(), 0) << "the beam should tear";
}

}  // namespace
