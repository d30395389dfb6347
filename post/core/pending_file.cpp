// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/pending_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <streambuf>
#include <vector>

#include "core/error.h"

namespace ohmdem::post {

namespace {

mode_t current_umask()
{
  const mode_t m = ::umask(0);
  ::umask(m);
  return m;
}

}  // namespace

PendingFile::PendingFile(const std::string &target) : target_(target), dest_(target)
{
  // /dev/stdout, /proc/self/fd/N: the stream a shell opened (a redirect), written as it is
  if (target.rfind("/dev/", 0) == 0 || target.rfind("/proc/", 0) == 0) {
    in_place_ = true;
    path_ = target;
    struct stat st {};
    existed_ = ::stat(target.c_str(), &st) == 0;
    return;
  }
  struct stat st {};
  if (::lstat(target.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    if (char *real = ::realpath(target.c_str(), nullptr)) {  // the link's file, not the link
      dest_ = real;
      std::free(real);
    }
  }
  if (::stat(dest_.c_str(), &st) == 0) {
    existed_ = true;
    mode_ = st.st_mode & 07777;
    if (!S_ISREG(st.st_mode)) {  // a device, a FIFO: written as it is
      in_place_ = true;
      path_ = target;
      return;
    }
  }
  const auto slash = dest_.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : dest_.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? dest_ : dest_.substr(slash + 1);
  std::string tmpl = dir + "." + base + ".tmp-XXXXXX";
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  const int fd = ::mkstemp(buf.data());
  if (fd < 0) {
    // a folder where no new file can be made may still hold a writable target
    if (errno == EACCES || errno == EPERM) {
      in_place_ = true;
      path_ = target;
      return;
    }
    throw Error("cannot write '" + target + "': " + std::strerror(errno));
  }
  ::close(fd);
  path_ = buf.data();
}

PendingFile::~PendingFile()
{
  if (!committed_ && !in_place_) ::unlink(path_.c_str());
}

std::string PendingFile::commit()
{
  if (in_place_) {
    committed_ = true;
    return "";
  }
  ::chmod(path_.c_str(), existed_ ? mode_ : 0666 & ~current_umask());
  if (::rename(path_.c_str(), dest_.c_str()) != 0) return std::strerror(errno);
  committed_ = true;
  return "";
}

// A buffer over a file descriptor that keeps the errno of the first write that failed.
class PendingStream::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd), buf_(1 << 16) { setp(buf_.data(), buf_.data() + buf_.size()); }
  ~Buffer() override
  {
    if (fd_ >= 0) ::close(fd_);
  }
  Buffer(const Buffer &) = delete;
  Buffer &operator=(const Buffer &) = delete;

  int error() const { return error_; }
  void close()
  {
    drain();
    if (fd_ >= 0 && ::close(fd_) != 0 && !error_) error_ = errno;  // a delayed write error
    fd_ = -1;
  }

 protected:
  int_type overflow(int_type c) override
  {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain()
  {
    const char *p = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left && !error_) {
      const ssize_t n = ::write(fd_, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        error_ = n < 0 ? errno : EIO;
        break;
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
    setp(buf_.data(), buf_.data() + buf_.size());
    return !error_;
  }

  int fd_;
  std::vector<char> buf_;
  int error_ = 0;
};

PendingStream::PendingStream(const std::string &target)
    : file_(std::make_unique<PendingFile>(target))
{
  const int flags = O_WRONLY | O_TRUNC | O_CLOEXEC | (file_->in_place() ? O_CREAT : 0);
  const int fd = ::open(file_->path().c_str(), flags, 0666);
  if (fd < 0) throw Error("cannot write '" + target + "': " + std::strerror(errno));
  buf_ = std::make_unique<Buffer>(fd);
  stream_ = std::make_unique<std::ostream>(buf_.get());
}

PendingStream::~PendingStream() = default;

std::ostream &PendingStream::stream()
{
  return *stream_;
}

std::string PendingStream::finish()
{
  stream_->flush();
  buf_->close();
  if (buf_->error()) return std::strerror(buf_->error());
  if (stream_->bad()) return "the output could not be written";
  return file_->commit();
}

}  // namespace ohmdem::post
