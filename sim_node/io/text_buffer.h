#pragma once
// Text built in place: the rows a CSV file holds until they are written (io/csv_writer.h).
// Numbers are formatted straight into the buffer's free space (Reserve, then Commit at the
// end written) instead of through a temporary string; the space grows geometrically and is
// kept across clear(), so a run's rows stop allocating after the first flush.

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <memory>

namespace towsim::io {

class TextBuffer {
 public:
  // room for n more characters from end(), which stays valid until the next Reserve
  char* Reserve(size_t n) {
    if (size_ + n > capacity_) Grow(size_ + n);
    return data_.get() + size_;
  }
  // the text now ends at `end` (within the room of the last Reserve)
  void Commit(char* end) { size_ = static_cast<size_t>(end - data_.get()); }
  void Append(const char* text, size_t n) {
    if (n == 0) return;
    std::memcpy(Reserve(n), text, n);
    size_ += n;
  }
  void Push(char c) {
    *Reserve(1) = c;
    ++size_;
  }

  const char* data() const { return data_.get(); }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() { size_ = 0; }

 private:
  void Grow(size_t needed) {
    const size_t capacity = std::max(needed, 2 * capacity_ + 256);
    std::unique_ptr<char[]> data(new char[capacity]);
    if (size_ > 0) std::memcpy(data.get(), data_.get(), size_);
    data_ = std::move(data);
    capacity_ = capacity;
  }

  std::unique_ptr<char[]> data_;
  size_t size_ = 0, capacity_ = 0;
};

}  // namespace towsim::io
