// SPDX-License-Identifier: GPL-2.0-or-later
// The source line of each row of a table, stored as runs of consecutive lines: a data file
// whose rows follow each other costs a few words instead of one per row (for messages only).
#ifndef OHMDEM_POST_ROW_LINES_H
#define OHMDEM_POST_ROW_LINES_H

#include <algorithm>
#include <cstddef>
#include <vector>

namespace ohmdem::post {

class RowLines {
 public:
  void push_back(std::size_t line)
  {
    if (runs_.empty() || line != last_ + 1) runs_.push_back({size_, line});
    last_ = line;
    ++size_;
  }
  std::size_t operator[](std::size_t row) const  // row < size(); 0 (no line) otherwise
  {
    if (row >= size_) return 0;
    auto it = std::upper_bound(runs_.begin(), runs_.end(), row,
                               [](std::size_t r, const Run &u) { return r < u.row; });
    --it;
    return it->line + (row - it->row);
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t back() const { return last_; }
  std::size_t runs() const { return runs_.size(); }  // storage used, in (row, line) pairs
  // The lines of rows [r0, r1).
  RowLines slice(std::size_t r0, std::size_t r1) const
  {
    RowLines out;
    for (std::size_t r = r0; r < r1 && r < size_;) {
      auto it = std::upper_bound(runs_.begin(), runs_.end(), r,
                                 [](std::size_t x, const Run &u) { return x < u.row; });
      const std::size_t run_end = it == runs_.end() ? size_ : it->row;
      --it;
      const std::size_t stop = std::min(run_end, r1);
      out.runs_.push_back({out.size_, it->line + (r - it->row)});
      out.size_ += stop - r;
      out.last_ = it->line + (stop - 1 - it->row);
      r = stop;
    }
    return out;
  }

 private:
  struct Run {
    std::size_t row, line;  // the run starts at `row`, which is on `line`
  };
  std::vector<Run> runs_;
  std::size_t size_ = 0, last_ = 0;
};

}  // namespace ohmdem::post

#endif
