// A minimal non-owning view (std::span is C++20; the core stays C++17).
#pragma once
#include <cstddef>
#include <vector>

namespace sma {

template <class T>
class span {
 public:
  span(T* data, std::size_t size) : data_(data), size_(size) {}
  template <class U>
  span(std::vector<U>& v) : data_(v.data()), size_(v.size()) {}
  template <class U>
  span(const std::vector<U>& v) : data_(v.data()), size_(v.size()) {}
  T& operator[](std::size_t i) const { return data_[i]; }
  std::size_t size() const { return size_; }
  T* begin() const { return data_; }
  T* end() const { return data_ + size_; }

 private:
  T* data_;
  std::size_t size_;
};

}  // namespace sma
