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
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
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
  EXPECT_NE(r.output.find("exploded at step"), std::string::npos) << r.output;
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

}  // namespace
