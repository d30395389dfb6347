// SPDX-License-Identifier: GPL-2.0-or-later
// A file written under a temporary name beside its target and renamed onto it only once whole:
// a failed write (a full disk, a killed process, a failed gnuplot) leaves neither an empty nor
// a cut file, and a file that was there before unchanged.
#ifndef OHMDEM_POST_PENDING_FILE_H
#define OHMDEM_POST_PENDING_FILE_H

#include <memory>
#include <ostream>
#include <string>

namespace ohmdem::post {

class PendingFile {
 public:
  // Creates the temporary file (".NAME.tmp-XXXXXX" beside the target; a symbolic link's file is
  // replaced, not the link). A target under /dev/ or /proc/ (/dev/stdout: a shell's
  // redirect), one that is not a regular file (/dev/null, a FIFO, a terminal), or one in a
  // folder where no new file can be made, is written in place: path() is the target itself.
  // Throws Error("cannot write 'T': reason").
  explicit PendingFile(const std::string &target);
  ~PendingFile();  // removes the temporary file unless committed
  PendingFile(const PendingFile &) = delete;
  PendingFile &operator=(const PendingFile &) = delete;

  const std::string &path() const { return path_; }         // where to write
  const std::string &target() const { return target_; }     // as given
  bool in_place() const { return in_place_; }               // path() is the target
  bool replaces() const { return existed_ && !in_place_; }  // an older file is replaced
  // Gives the temporary file the target's mode (else 0666 less the umask) and renames it onto
  // the target: "" when done, else the system's reason.
  std::string commit();

 private:
  std::string target_, dest_, path_;
  bool in_place_ = false, existed_ = false, committed_ = false;
  unsigned mode_ = 0;
};

// A PendingFile written through a stream that keeps the system's reason of the first failed
// write (std::ofstream loses it): "No space left on device", "File too large".
class PendingStream {
 public:
  explicit PendingStream(const std::string &target);
  ~PendingStream();  // an unfinished stream (not finish()ed) leaves nothing
  PendingStream(const PendingStream &) = delete;
  PendingStream &operator=(const PendingStream &) = delete;

  std::ostream &stream();
  // Flushes, closes and commits: "" when the file is whole in place, else the reason it is not
  // (the temporary file is then removed).
  std::string finish();
  const PendingFile &file() const { return *file_; }

 private:
  class Buffer;
  std::unique_ptr<PendingFile> file_;
  std::unique_ptr<Buffer> buf_;
  std::unique_ptr<std::ostream> stream_;
};

}  // namespace ohmdem::post

#endif
