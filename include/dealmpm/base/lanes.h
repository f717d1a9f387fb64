#pragma once

namespace dealmpm
{
  /** Four and two doubles as one vector each (GCC's vector extension:
   * AVX, or SSE2 pairs), for the sweeps' nodes interleaved in blocks:
   * element-wise products and sums, the same numbers as the scalar ones. */
  typedef double Lanes4 __attribute__((vector_size(32)));
  typedef double Lanes2 __attribute__((vector_size(16)));

  /** The lanes at @p x, any alignment. */
  template <typename Lanes>
  inline __attribute__((always_inline)) Lanes
  load_lanes(const double *x)
  {
    Lanes lanes;
    __builtin_memcpy(&lanes, x, sizeof(lanes));
    return lanes;
  }

  /** Stores @p lanes at @p x, any alignment. */
  template <typename Lanes>
  inline __attribute__((always_inline)) void
  store_lanes(double *x, const Lanes &lanes)
  {
    __builtin_memcpy(x, &lanes, sizeof(lanes));
  }
} // namespace dealmpm
