// fuzz_sampler.cpp — libFuzzer harness for the C ABI (built with -DSTIPPLE_FUZZ=ON and clang; see the `fuzz`
// preset). The input drives a sampler description (pattern, N, layout, names, struct sizes, reserved fields)
// and then fill/sample calls with arbitrary pixels, indices and buffer capacities. Buffers are allocated at
// exactly the capacity claimed, so ASan catches any write past what the library was told it may use.
// Every call must return a status; none may crash, leak or write out of bounds.
#include <stipple/stipple.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

class Input {
 public:
  Input(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  template <typename T>
  T take() {
    T value{};
    const size_t n = std::min(sizeof(T), size_ - offset_);
    std::memcpy(&value, data_ + offset_, n);
    offset_ += n;
    return value;
  }
  bool empty() const { return offset_ >= size_; }

 private:
  const uint8_t* data_;
  size_t size_, offset_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Input in(data, size);
  const uint32_t dimensionCount = in.take<uint8_t>() % 9;  // 0 tests the empty layout
  std::vector<stipple_dimension_desc> dims(dimensionCount ? dimensionCount : 1);
  std::vector<std::string> names(dims.size());
  for (size_t d = 0; d < dims.size(); ++d) {
    // Sizes never exceed the real struct: a host that claims more than it passes is wrong, not the library.
    dims[d].struct_size = in.take<uint8_t>() & 1 ? sizeof(stipple_dimension_desc)
                                                 : in.take<uint8_t>() % (sizeof(stipple_dimension_desc) + 1);
    dims[d].arity = in.take<uint8_t>() % 5;
    dims[d].count = in.take<uint8_t>() % 6;
    dims[d].reserved = in.take<uint8_t>() == 0xff;
    const uint8_t nameLength = in.take<uint8_t>() % 80;
    for (uint8_t i = 0; i < nameLength; ++i) names[d].push_back(char(1 + in.take<uint8_t>() % 126));
    dims[d].name = nameLength ? names[d].c_str() : nullptr;
  }
  stipple_sampler_desc desc{};
  desc.struct_size = in.take<uint8_t>() & 1 ? sizeof desc : in.take<uint8_t>() % (sizeof desc + 1);
  desc.pattern = in.take<uint8_t>() % 6;
  desc.samples_per_pixel = in.take<uint16_t>() % 1100;  // bounded so poisson-seed stays fast
  desc.dimension_count = dimensionCount;
  desc.seed = in.take<uint64_t>();
  desc.dimensions = in.take<uint8_t>() == 0xfe ? nullptr : dims.data();
  desc.flags = in.take<uint8_t>() == 0xfd;

  stipple_sampler sampler = nullptr;
  if (stipple_sampler_create(&desc, &sampler) != STIPPLE_OK) {
    (void)stipple_last_error_message();
    return 0;
  }
  for (int call = 0; call < 8 && !in.empty(); ++call) {
    const uint32_t x = in.take<uint32_t>(), y = in.take<uint32_t>();
    const uint32_t dimension = in.take<uint8_t>() % 10;
    const size_t capacity = in.take<uint16_t>() % 20000;
    std::vector<float> out(capacity);
    switch (in.take<uint8_t>() % 3) {
      case 0: stipple_sampler_fill_pixel(sampler, x, y, dimension, out.data(), capacity); break;
      case 1: stipple_sampler_sample(sampler, x, y, in.take<uint16_t>(), dimension, out.data(), capacity); break;
      default: stipple_sampler_sample_independent(sampler, x, y, in.take<uint32_t>(), dimension, out.data(), capacity);
    }
    for (float v : out)
      if (v < 0.0f || v >= 1.0f) __builtin_trap();  // a value outside [0,1) (untouched buffers hold 0)
  }
  stipple_sampler_release(sampler);
  return 0;
}
