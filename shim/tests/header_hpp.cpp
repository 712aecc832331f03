// header_hpp.cpp — stipple.hpp compiles alone as strict C++17 (shim.header_hpp).
#include <stipple/stipple.hpp>
