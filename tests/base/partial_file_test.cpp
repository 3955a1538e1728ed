// Temporary files (partial_file.h): an output's temporary is made at once,
// under a name nobody can foresee, never through a link planted where it
// would go, and readable by its user alone until it is whole; scratch
// files live in a folder of the process's own, gone with the last of them
// or with the signal cleanup.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "base/partial_file.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

std::string host() {
  char name[256] = {};
  std::string h = gethostname(name, sizeof name - 1) == 0 && name[0] ? name : "host";
  for (char& c : h)
    if (c == '/' || c == '.') c = '_';
  return h;
}

std::string text_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

mode_t mode_of(const fs::path& path) {
  struct stat st {};
  return lstat(path.c_str(), &st) == 0 ? st.st_mode : 0;
}

// The ID of a process that has ended.
pid_t dead_pid() {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  return child;
}

// The name an output's temporary had before: ".NAME.partial-HOST-PID.EXT",
// which anyone could foresee for the next process IDs.
TEST(PartialFile, ALinkPlantedAtTheForeseeableNameIsNotWrittenThrough) {
  const fs::path dir = test_temp_dir("partial_link", true);
  const fs::path victim = dir / "victim.txt";
  std::ofstream(victim) << "the victim's";
  fs::create_symlink(victim, dir / (".x.partial-" + host() + "-" + std::to_string(getpid()) + ".png"));
  PartialFile file((dir / "x.png").string());
  file.write("new", 3);
  file.commit();
  EXPECT_EQ(text_of(victim), "the victim's");
  EXPECT_TRUE(S_ISREG(mode_of(dir / "x.png")));
  EXPECT_EQ(text_of(dir / "x.png"), "new");
}

TEST(PartialFile, TheTemporaryIsMadeAtOnceUnderANameOfItsOwnForItsUserAlone) {
  const fs::path dir = test_temp_dir("partial_names", true);
  const PartialFile a((dir / "y.png").string()), b((dir / "y.png").string());
  EXPECT_NE(a.path(), b.path());
  const std::string prefix = ".y.partial-" + host() + "-" + std::to_string(getpid()) + "-";
  for (const PartialFile* file : {&a, &b}) {
    const fs::path path = file->path();
    EXPECT_EQ(path.parent_path(), dir);
    EXPECT_EQ(path.filename().string().rfind(prefix, 0), 0u) << path;
    EXPECT_EQ(path.extension(), ".png");
    EXPECT_EQ(path.filename().string().size(), prefix.size() + 6 + 4) << path;  // six random letters
    EXPECT_TRUE(S_ISREG(mode_of(path))) << path;
    EXPECT_EQ(mode_of(path) & 0777, 0600u) << path;
  }
}

TEST(PartialFile, TheFinishedFileHasTheModeOfAnyNewFile) {
  const fs::path dir = test_temp_dir("partial_mode", true);
  const mode_t mask = umask(0);
  umask(mask);
  PartialFile file((dir / "z.pov").string());
  file.write("blob", 4);
  file.commit();
  EXPECT_EQ(mode_of(dir / "z.pov") & 0777, 0666u & ~mask);
  EXPECT_EQ(fs::directory_iterator(dir)->path().filename(), "z.pov");  // the temporary is gone
}

TEST(PartialFile, AFileNeverCommittedLeavesNothing) {
  const fs::path dir = test_temp_dir("partial_abandoned", true);
  { const PartialFile file((dir / "w.png").string()); }
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_THROW(PartialFile file((dir / "missing" / "w.png").string()), std::runtime_error);
}

// A killed run's temporaries, named as now and as before, are removed;
// a live process's and another host's are not.
TEST(PartialFile, AKilledRunsTemporariesAreRemoved) {
  const fs::path dir = test_temp_dir("partial_stale", true);
  const std::string dead = std::to_string(dead_pid()), alive = std::to_string(getpid());
  for (const std::string& name : {".a.partial-" + host() + "-" + dead + "-Ab12Cd.png",
                                  ".b.partial-" + host() + "-" + dead + ".png",
                                  ".c.partial-" + host() + "-" + alive + "-Ab12Cd.png",
                                  ".d.partial-elsewhere-" + dead + "-Ab12Cd.png"})
    std::ofstream(dir / name) << "left";
  EXPECT_EQ(remove_stale_partial_files(dir), 2);
  EXPECT_FALSE(fs::exists(dir / (".a.partial-" + host() + "-" + dead + "-Ab12Cd.png")));
  EXPECT_FALSE(fs::exists(dir / (".b.partial-" + host() + "-" + dead + ".png")));
  EXPECT_TRUE(fs::exists(dir / (".c.partial-" + host() + "-" + alive + "-Ab12Cd.png")));
  EXPECT_TRUE(fs::exists(dir / (".d.partial-elsewhere-" + dead + "-Ab12Cd.png")));
}

TEST(ScratchFile, LivesInAFolderOfTheProcesssOwn) {
  fs::path folder, path;
  {
    const ScratchFile file("test", ".txt");
    folder = scratch_folder();
    path = file.path();
    ASSERT_FALSE(folder.empty());
    EXPECT_EQ(folder.parent_path(), fs::temp_directory_path());
    const std::string prefix = "hsb-" + host() + "-" + std::to_string(getpid()) + "-";
    EXPECT_EQ(folder.filename().string().rfind(prefix, 0), 0u) << folder;
    EXPECT_EQ(folder.filename().string().size(), prefix.size() + 6) << folder;  // six random letters
    struct stat st {};
    ASSERT_EQ(lstat(folder.c_str(), &st), 0);
    EXPECT_TRUE(S_ISDIR(st.st_mode));
    EXPECT_EQ(st.st_mode & 0777, 0700u);
    EXPECT_EQ(st.st_uid, geteuid());
    EXPECT_EQ(path.parent_path(), folder);
    EXPECT_EQ(mode_of(path) & 0777, 0600u);
    EXPECT_FALSE(file.written());  // made empty: no answer yet
    std::ofstream(path) << "an answer";
    EXPECT_TRUE(file.written());
    const ScratchFile second("test", ".txt");
    EXPECT_EQ(fs::path(second.path()).parent_path(), folder);
    EXPECT_NE(second.path(), file.path());
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(folder));
  EXPECT_EQ(scratch_folder(), "");
}

TEST(ScratchFile, TwoProcessesFoldersDiffer) {
  int pipe_ends[2];
  ASSERT_EQ(pipe(pipe_ends), 0);
  const pid_t child = fork();
  if (child == 0) {
    std::string folder;
    {
      const ScratchFile file("child", ".txt");
      folder = scratch_folder();
    }
    folder += fs::exists(folder) ? " left" : "";
    const ssize_t ignored = write(pipe_ends[1], folder.data(), folder.size());
    (void)ignored;
    _exit(0);
  }
  close(pipe_ends[1]);
  const ScratchFile file("parent", ".txt");
  std::string theirs;
  char buffer[4096];
  for (ssize_t n; (n = read(pipe_ends[0], buffer, sizeof buffer)) > 0;) theirs.append(buffer, std::size_t(n));
  close(pipe_ends[0]);
  waitpid(child, nullptr, 0);
  ASSERT_FALSE(theirs.empty());
  EXPECT_EQ(theirs.find(" left"), std::string::npos) << theirs;
  EXPECT_NE(theirs, scratch_folder());
  EXPECT_EQ(fs::path(theirs).filename().string().rfind("hsb-" + host() + "-" + std::to_string(child) + "-", 0), 0u)
      << theirs;
}

// What a signal handler calls (remove_partial_files) removes the scratch
// files and their folder, with what a child killed mid-read left there.
TEST(ScratchFile, TheSignalCleanupRemovesTheFolder) {
  const ScratchFile file("signal", ".txt");
  const fs::path folder = scratch_folder();
  ASSERT_TRUE(fs::exists(file.path()));
  for (int i = 0; i < 300; ++i) std::ofstream(folder / (".child" + std::to_string(i) + ".partial-vtk")) << i;
  remove_partial_files();
  EXPECT_FALSE(fs::exists(file.path()));
  EXPECT_FALSE(fs::exists(folder));
}

}  // namespace
}  // namespace hsb
