// Output files of the mdcs commands: every write checked (a full disk, a file size limit or a vanished folder is
// an error, exit code 1, never a truncated file left behind as if it were a result), output names that cannot
// leave the output folder, and PNG copies of SVG pictures through rsvg-convert (run without a shell).
#ifndef MDCS_CLI_OUTPUT_H
#define MDCS_CLI_OUTPUT_H

#include "cli_options.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace mdcs_cli {

// A base name given on the command line (--name): letters, digits, '.', '_', '-', at most 100 characters, not
// starting with '.' or '-', so that it names a file inside the output folder and nothing else.
inline std::string checked_file_name(const std::string& name, const std::string& option)
{
  const bool bad_char = name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789._-") != std::string::npos;
  if(name.empty() || name.size() > 100 || bad_char || name[0] == '.' || name[0] == '-')
    throw Usage_error(option + ": '" + name + "' is not a plain file name (letters, digits, '.', '_', '-'; at most 100 "
                                "characters; not starting with '.' or '-'): output files stay inside the output folder");
  return name;
}

namespace output_detail {

// A stream buffer on a file descriptor that remembers the first failed write (errno), so that the message says
// why ("No space left on device", "File too large").
class Fd_buffer : public std::streambuf
{
public:
  explicit Fd_buffer(int fd) : fd_(fd), buffer_(1 << 16) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  Fd_buffer(const Fd_buffer&) = delete;
  Fd_buffer& operator=(const Fd_buffer&) = delete;
  ~Fd_buffer() override
  {
    if(fd_ >= 0) ::close(fd_);
  }

  int error() const { return error_; }

  bool close()
  {
    const bool flushed = drain();
    if(fd_ >= 0) {
      if(::close(fd_) != 0 && error_ == 0) error_ = errno;
      fd_ = -1;
    }
    return flushed && error_ == 0;
  }

protected:
  int_type overflow(int_type c) override
  {
    if(!drain()) return traits_type::eof();
    if(!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

private:
  bool drain()
  {
    const char* p = pbase();
    while(p < pptr() && error_ == 0) {
      const ssize_t n = ::write(fd_, p, std::size_t(pptr() - p));
      if(n < 0 && errno == EINTR) continue;
      if(n <= 0) error_ = n < 0 ? errno : EIO;
      else p += n;
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return error_ == 0;
  }

  int fd_;
  std::vector<char> buffer_;
  int error_ = 0;
};

} // namespace output_detail

// One output file. A regular file is written as PATH.part and renamed to PATH by commit(), so that a failed run
// leaves no truncated PATH; other paths (a device such as /dev/stdout, a pipe) are written directly.
// commit() throws std::runtime_error if anything failed; a file never committed is removed.
class Output_file
{
public:
  explicit Output_file(const std::string& path)
    : path_(path), written_(written_path(path)), buffer_(open_or_throw(written_, path)), stream_(&buffer_)
  {
    stream_.precision(17);
  }
  Output_file(const Output_file&) = delete;
  Output_file& operator=(const Output_file&) = delete;

  ~Output_file()
  {
    if(!committed_) {
      if(written_ != path_) ::unlink(written_.c_str());
    }
  }

  std::ostream& stream() { return stream_; }
  template <class T> Output_file& operator<<(const T& value)
  {
    stream_ << value;
    return *this;
  }

  void commit()
  {
    stream_.flush();
    const bool ok = !stream_.fail() && buffer_.close();
    if(!ok || (written_ != path_ && std::rename(written_.c_str(), path_.c_str()) != 0)) {
      const int e = buffer_.error() ? buffer_.error() : errno;
      if(written_ != path_) ::unlink(written_.c_str());
      committed_ = true; // nothing left to clean up
      throw std::runtime_error("cannot write '" + path_ + "': " + (e ? std::strerror(e) : "write error"));
    }
    committed_ = true;
  }

  const std::string& path() const { return path_; }

private:
  static std::string written_path(const std::string& path)
  {
    struct stat st;
    if(::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return path + ".part";
    if(S_ISDIR(st.st_mode)) throw std::runtime_error("cannot write '" + path + "': it is a folder");
    return path; // a device or a pipe
  }
  static int open_or_throw(const std::string& written, const std::string& path)
  {
    const int fd = ::open(written.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if(fd < 0) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
    return fd;
  }

  std::string path_, written_;
  output_detail::Fd_buffer buffer_;
  std::ostream stream_;
  bool committed_ = false;
};

inline void write_text_file(const std::string& path, const std::string& text)
{
  Output_file f(path);
  f << text;
  f.commit();
}

// The output folder of a command (created if needed) and the files written into it, for the summaries.
inline std::filesystem::path prepare_output_folder(const std::string& folder)
{
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if(ec || !std::filesystem::is_directory(folder))
    throw std::runtime_error("cannot create the output folder '" + folder + "'" + (ec ? ": " + ec.message() : std::string()));
  return std::filesystem::path(folder);
}

// Writes a PNG copy of an SVG picture with rsvg-convert when it is installed; returns whether it did (false: not
// installed). The program runs without a shell (no quoting of the paths); its PNG is written as .part and renamed
// only when it succeeded; a failure (a full disk) throws std::runtime_error like any other failed write.
inline bool svg_to_png(const std::filesystem::path& svg)
{
  std::filesystem::path png = svg;
  png.replace_extension(".png");
  const std::string part = png.string() + ".part", input = svg.string();
  std::vector<std::string> args = {"rsvg-convert", "-w", "1000", "-b", "white", "-f", "png", "-o", part, input};
  std::vector<char*> argv;
  for(std::string& a : args) argv.push_back(&a[0]);
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "rsvg-convert", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if(spawned != 0) return false; // not installed
  int status = 0;
  while(::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if(WIFEXITED(status) && WEXITSTATUS(status) == 127) { // posix_spawnp's child found no program to run
    ::unlink(part.c_str());
    return false;
  }
  std::error_code ec;
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 && std::filesystem::file_size(part, ec) > 0 && !ec;
  if(!ok || std::rename(part.c_str(), png.string().c_str()) != 0) {
    ::unlink(part.c_str());
    throw std::runtime_error("cannot write '" + png.string() + "': rsvg-convert failed" +
                             (WIFEXITED(status) ? " with exit code " + std::to_string(WEXITSTATUS(status)) : std::string(" (killed)")) +
                             " (--no-picture skips the pictures)");
  }
  return true;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_OUTPUT_H
