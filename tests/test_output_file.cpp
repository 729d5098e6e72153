// How every writer creates a file (include/sgtllc/io/output_file.h): a planted symlink never redirects a save,
// the temporary file is hidden, exclusive and of a normal file's mode, and it is removed on errors and on SIGTERM;
// one left by SIGKILL is recognisable and no folder reader takes it for a frame.
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/config.h"
#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/io/output_file.h"
#include "sgtllc/io/sequence.h"
#include "test_io_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using testing::HasSubstr;

class OutputFile : public test::TempDirTest {
 protected:
  std::string readAll(const std::string& p) const {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  std::vector<std::string> entries(const std::string& folder = "") const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_ / folder)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  /// Runs @p body in a child process; returns its wait status.
  template <typename F>
  int inChild(F&& body) const {
    const pid_t pid = ::fork();
    if (pid == 0) {
      body();
      ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
  }
};

TEST_F(OutputFile, SymlinksPlantedAtPredictableNamesAreNeverFollowed) {
  const std::string victim = write("victim.txt", "precious\n");
  const std::string out = path("out.txt");
  // The names an earlier version used (PATH.tmpPID-N), and hidden names of the current pattern with guessed letters.
  for (int n = 0; n < 32; ++n) {
    fs::create_symlink(victim, out + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(n));
  }
  fs::create_symlink(victim, path(".out.txt.sgtllc-tmp-AAAAAAAAAAAA"));
  for (int i = 0; i < 3; ++i) io::writeFileAtomically(out, "saved " + std::to_string(i) + "\n", io::Overwrite::kReplace);
  EXPECT_EQ(readAll(victim), "precious\n");
  EXPECT_EQ(fs::symlink_status(out).type(), fs::file_type::regular);
  EXPECT_EQ(readAll(out), "saved 2\n");
  EXPECT_EQ(entries().size(), 1u + 1u + 32u + 1u);  // victim, out and the 33 links: nothing else left
}

TEST_F(OutputFile, TheTemporaryIsHiddenExclusiveBesideItsTargetAndOfANormalFilesMode) {
  const mode_t old_umask = ::umask(027);
  const std::string out = path("sub/plot.png");
  fs::create_directories(path("sub"));
  std::string seen;
  io::writeThroughTemporary(out, io::Overwrite::kRefuse, [&](const std::string& tmp) {
    seen = tmp;
    const fs::path p(tmp);
    EXPECT_EQ(p.parent_path(), fs::path(out).parent_path());
    EXPECT_TRUE(io::isTemporaryFileName(p.filename().string())) << tmp;
    EXPECT_THAT(p.filename().string(), testing::StartsWith(".plot.png.sgtllc-tmp-"));
    EXPECT_EQ(fs::symlink_status(p).type(), fs::file_type::regular);  // created, empty, before the writer runs
    EXPECT_EQ(fs::file_size(p), 0u);
    std::ofstream(tmp, std::ios::binary) << "png";
  });
  ::umask(old_umask);
  struct stat st {};
  ASSERT_EQ(::stat(out.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);  // 0666 less the umask, as fopen would give; not mkstemp's 0600
  EXPECT_EQ(readAll(out), "png");
  EXPECT_FALSE(fs::exists(seen));
  // Two saves draw two names.
  std::string a, b;
  io::writeThroughTemporary(path("a"), io::Overwrite::kRefuse, [&](const std::string& t) { a = t; });
  io::writeThroughTemporary(path("b"), io::Overwrite::kRefuse, [&](const std::string& t) { b = t; });
  EXPECT_NE(fs::path(a).filename().string().substr(3), fs::path(b).filename().string().substr(3));
}

TEST_F(OutputFile, AWriterThatFindsALinkInsteadOfItsTemporaryFileIsRefused) {
  const std::string victim = write("victim.txt", "precious\n");
  const std::string out = path("out.png");
  EXPECT_THAT(
      [&] {
        io::writeThroughTemporary(out, io::Overwrite::kReplace, [&](const std::string& tmp) {
          fs::remove(tmp);  // someone swaps the file for a link between creation and the writer's open
          fs::create_symlink(victim, tmp);
        });
      },
      testing::ThrowsMessage<Error>(AllOf(HasSubstr(out), HasSubstr("was replaced"))));
  EXPECT_EQ(readAll(victim), "precious\n");
  EXPECT_FALSE(fs::exists(fs::symlink_status(out)));
  EXPECT_EQ(entries(), std::vector<std::string>{"victim.txt"});
}

TEST_F(OutputFile, ErrorsLeaveNothingBehind) {
  EXPECT_THROW(io::writeThroughTemporary(path("x.png"), io::Overwrite::kReplace,
                                         [](const std::string&) { throw Error("the writer failed"); }),
               Error);
  write("taken.txt", "theirs");
  EXPECT_THAT([&] { io::writeFileAtomically(path("taken.txt"), "ours", io::Overwrite::kRefuse); },
              testing::ThrowsMessage<Error>(HasSubstr("file exists")));
  EXPECT_THAT([&] { io::writeFileAtomically(path("missing/x.txt"), "ours", io::Overwrite::kReplace); },
              testing::ThrowsMessage<Error>(AllOf(HasSubstr(path("missing/x.txt")), HasSubstr("No such file"))));
  EXPECT_EQ(entries(), std::vector<std::string>{"taken.txt"});
  EXPECT_EQ(readAll(path("taken.txt")), "theirs");
}

TEST_F(OutputFile, PiecesAreWrittenInOrderAsOneFile) {
  // Small pieces gathered into megabyte writes, a piece larger than that written on its own, empty pieces, and a
  // gathered run that would overflow a megabyte flushed first.
  const std::string big(3u << 20, 'b'), near(1000000, 'n');
  std::vector<std::string> small;
  for (int i = 0; i < 5000; ++i) small.push_back(std::to_string(i) + ",");
  std::vector<std::string_view> pieces = {"head;", ""};
  for (const std::string& piece : small) pieces.push_back(piece);
  pieces.push_back(big);
  pieces.push_back(near);
  pieces.push_back(near);
  pieces.push_back("tail");
  std::string joined;
  for (std::string_view piece : pieces) joined += piece;
  io::writeFileAtomically(path("pieces.bin"), pieces, io::Overwrite::kRefuse);
  EXPECT_EQ(readAll(path("pieces.bin")), joined);
  EXPECT_EQ(entries(), std::vector<std::string>{"pieces.bin"});
  io::writeFileAtomically(path("none.bin"), std::vector<std::string_view>{}, io::Overwrite::kRefuse);
  EXPECT_EQ(fs::file_size(path("none.bin")), 0u);
  EXPECT_THAT([&] { io::writeFileAtomically(path("pieces.bin"), pieces, io::Overwrite::kRefuse); },
              testing::ThrowsMessage<Error>(HasSubstr("file exists")));
}

TEST_F(OutputFile, ALongNameStillGetsATemporaryFile) {
  const std::string name(250, 'n');
  io::writeFileAtomically(path(name), "long\n", io::Overwrite::kRefuse);
  EXPECT_EQ(readAll(path(name)), "long\n");
  EXPECT_EQ(entries(), std::vector<std::string>{name});
}

TEST_F(OutputFile, SigtermDuringASaveRemovesTheTemporaryFileAndStillEndsTheProcess) {
  const std::string out = path("map.sgtmap");
  const int status = inChild([&] {
    io::writeThroughTemporary(out, io::Overwrite::kRefuse, [](const std::string& tmp) {
      std::ofstream(tmp, std::ios::binary) << std::string(100000, 'x');
      ::raise(SIGTERM);
    });
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << status;
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_TRUE(entries().empty());
}

TEST_F(OutputFile, AnApplicationsOwnSigintHandlerIsKept) {
  const int status = inChild([&] {
    static volatile sig_atomic_t caught = 0;
    void (*const own)(int) = [](int) { caught = 1; };
    ::signal(SIGINT, own);
    io::writeThroughTemporary(path("a.txt"), io::Overwrite::kRefuse, [](const std::string& tmp) {
      std::ofstream(tmp) << "a";
      ::raise(SIGINT);  // the application's handler runs, the save goes on
    });
    struct sigaction now {};
    ::sigaction(SIGINT, nullptr, &now);
    ::_exit(caught && now.sa_handler == own ? 3 : 4);
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);
  EXPECT_EQ(readAll(path("a.txt")), "a");
}

TEST_F(OutputFile, ALeftoverOfSigkillIsRecognisableAndNoReaderTakesItForAFrame) {
  // A sequence folder and a node folder, each with a save killed half way (SIGKILL cannot be caught: the file stays).
  write("seq/velodyne/000000.bin", std::string(16, '\0'));
  write("nodes/000000.txt", "1 2 3 0\n");
  for (const std::string& out : {path("seq/velodyne/000001.bin"), path("nodes/000001.txt")}) {
    const int status = inChild([&] {
      io::writeThroughTemporary(out, io::Overwrite::kRefuse, [](const std::string& tmp) {
        std::ofstream(tmp, std::ios::binary) << std::string(160, '\0');
        ::raise(SIGKILL);
      });
    });
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_FALSE(fs::exists(out));  // never a partial file under the final name
  }
  for (const std::string folder : {"seq/velodyne", "nodes"}) {
    const std::vector<std::string> names = entries(folder);
    ASSERT_EQ(names.size(), 2u) << folder;
    EXPECT_EQ(names[0].front(), '.');
    EXPECT_TRUE(io::isTemporaryFileName(names[0])) << names[0];
  }
  EXPECT_EQ(io::SequenceDir(path("seq"), io::SequenceLabels{false, ""}).size(), 1u);
  EXPECT_EQ(pipeline::FrameSource::nodeFiles(path("nodes"), Config{}).size(), 1u);
}

TEST_F(OutputFile, TheNextSaveRemovesALeftoverButNotALiveTemporary) {
  write("out/keep.txt", "k");
  const auto temporaries = [&] {
    size_t n = 0;
    for (const std::string& name : entries("out")) n += io::isTemporaryFileName(name);
    return n;
  };
  // A save in progress in another process, holding its temporary file until told to go on.
  int ready[2], go[2];
  ASSERT_EQ(::pipe(ready), 0);
  ASSERT_EQ(::pipe(go), 0);
  const pid_t live = ::fork();
  if (live == 0) {
    io::writeThroughTemporary(path("out/b.txt"), io::Overwrite::kRefuse, [&](const std::string& tmp) {
      char c = 'r';
      if (::write(ready[1], &c, 1) != 1 || ::read(go[0], &c, 1) != 1) ::_exit(5);
      std::ofstream(tmp) << "b";
    });
    ::_exit(0);
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  // A save killed half way: SIGKILL runs no handler, its temporary file stays.
  const int killed = inChild([&] {
    io::writeThroughTemporary(path("out/a.txt"), io::Overwrite::kRefuse, [](const std::string& tmp) {
      std::ofstream(tmp) << "partial";
      ::raise(SIGKILL);
    });
  });
  ASSERT_TRUE(WIFSIGNALED(killed));
  EXPECT_EQ(temporaries(), 2u);
  // The next process to save into the folder removes the leftover (its lock died with it), not the live one.
  const int next = inChild([&] { io::writeFileAtomically(path("out/c.txt"), "c", io::Overwrite::kRefuse); });
  ASSERT_TRUE(WIFEXITED(next));
  EXPECT_EQ(temporaries(), 1u);
  ASSERT_EQ(::write(go[1], &c, 1), 1);
  int status = 0;
  ::waitpid(live, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(temporaries(), 0u);
  EXPECT_EQ(readAll(path("out/b.txt")), "b");
  EXPECT_EQ(readAll(path("out/c.txt")), "c");
  EXPECT_EQ(readAll(path("out/keep.txt")), "k");
  EXPECT_FALSE(fs::exists(path("out/a.txt")));
  for (int fd : {ready[0], ready[1], go[0], go[1]}) ::close(fd);
}

TEST_F(OutputFile, AnEmptyNewTemporaryMayBeASaveBetweenItsCreationAndItsLock) {
  // open(2) and flock(2) are two calls: between them a save's file is empty, new and unlocked. Such a file must
  // survive another save's sweep of the folder; an empty one from over a minute ago is a leftover like any other.
  write("out/keep.txt", "k");
  const std::string fresh = write("out/.b.txt.sgtllc-tmp-Fresh0000000", "");
  const std::string stale = write("out/.a.txt.sgtllc-tmp-Stale0000000", "");
  const struct timespec old[2] = {{::time(nullptr) - 120, 0}, {::time(nullptr) - 120, 0}};
  ASSERT_EQ(::utimensat(AT_FDCWD, stale.c_str(), old, 0), 0);
  const int next = inChild([&] { io::writeFileAtomically(path("out/c.txt"), "c", io::Overwrite::kRefuse); });
  ASSERT_TRUE(WIFEXITED(next));
  EXPECT_EQ(WEXITSTATUS(next), 0);
  EXPECT_TRUE(fs::exists(fresh));
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_EQ(readAll(path("out/c.txt")), "c");
}

TEST_F(OutputFile, ConcurrentSavesIntoOneFolderAllLand) {
  // Threads of one process saving side by side (as `simulate` writes frames): the first save's sweep of the
  // folder must never take another's just-created temporary file for a leftover.
  fs::create_directories(dir_ / "many");
  std::vector<std::thread> threads;
  std::atomic<int> failures{0};
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < 50; ++i) {
        try {
          io::writeFileAtomically(path("many/" + std::to_string(t * 100 + i) + ".txt"), "x", io::Overwrite::kRefuse);
        } catch (const std::exception&) {
          ++failures;
        }
      }
    });
  }
  for (std::thread& th : threads) th.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_EQ(entries("many").size(), 200u);
}

TEST(OutputFileNames, OnlyTheTemporaryPatternIsRecognised) {
  EXPECT_TRUE(io::isTemporaryFileName(".a.bin.sgtllc-tmp-Ab3dEf6hIj9K"));
  EXPECT_FALSE(io::isTemporaryFileName("a.bin.sgtllc-tmp-Ab3dEf6hIj9K"));    // not hidden
  EXPECT_FALSE(io::isTemporaryFileName(".a.bin.sgtllc-tmp-Ab3dEf6hIj9"));    // 11 letters
  EXPECT_FALSE(io::isTemporaryFileName(".a.bin.sgtllc-tmp-Ab3dEf6hIj9.K"));  // not letters
  EXPECT_FALSE(io::isTemporaryFileName("000001.bin"));
  EXPECT_FALSE(io::isTemporaryFileName(".sgtllc-tmp-Ab3dEf6hIj9K"));
}

}  // namespace
}  // namespace sgtllc
