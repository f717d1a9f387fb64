#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dealmpm
{
  /** @p text with XML's special characters escaped (array names come
   * from material models, user code among them). */
  std::string
  xml_escaped(const std::string &text);

  /** The type of a VTU data array, as VTK names it. */
  enum class VtuType
  {
    Int32,
    Int64,
    Float32,
    Float64
  };

  /**
   * A named point-data array: n_components values per point, point after
   * point. Integer types keep their values in @p integers, real types in
   * @p reals; the narrower types are converted when written.
   */
  struct VtuArray
  {
    std::string               name;
    VtuType                   type;
    unsigned int              n_components;
    std::vector<std::int64_t> integers;
    std::vector<double>       reals;
  };

  /**
   * One rank's piece of a point cloud (or of a mesh: see connectivity) as
   * a VTK XML UnstructuredGrid, and the
   * .pvtu record over all pieces. We write it ourselves because deal.II's
   * writer stores every field as Float32, which cannot tell particle ids
   * past 2^24 apart. Points are Float64 (x, y, z; z = 0 in 2D), each point
   * is a VTK_VERTEX cell so that ParaView draws it, and the point data keep
   * their types. The data are binary in one appended block with UInt64
   * byte counts, array by array (no per-value formatting), raw or, on
   * request, zlib-compressed. A piece without
   * points declares the same arrays with their component counts, so that
   * readers accept it. Files are written through OutputFile (atomic; errors
   * throw OutputError).
   */
  class VtuPointCloud
  {
  public:
    /** Declare an array (before resize()); returns its index. */
    unsigned int
    add_array(const std::string &name,
              const VtuType      type,
              const unsigned int n_components);

    /** Size the points and every array for @p n_points (values zero). */
    void
    resize(const std::size_t n_points);

    std::size_t
    n_points() const
    {
      return points.size() / 3;
    }

    /** Its cells: those of @p connectivity, or one VTK_VERTEX per point
     * when that is empty. */
    std::size_t
    n_cells() const
    {
      return connectivity.empty() ? n_points() :
                                    connectivity.size() / points_per_cell;
    }

    /** Write this piece to @p path, each array compressed with zlib if
     * @p zlib (VTK's vtkZLibDataCompressor, one block per array). */
    void
    write_vtu(const std::string &path, const bool zlib = false) const;

    /** The record that lists @p pieces (names relative to it) with this
     * cloud's arrays. */
    void
    write_pvtu(const std::string              &path,
               const std::vector<std::string> &pieces) const;

    /** x, y, z of each point. */
    std::vector<double> points;

    std::vector<VtuArray> arrays;

    /** Cells of one VTK type (an FEM region's quads or hexahedra, a rigid
     * body's outline), @p points_per_cell point indices each, cell after
     * cell; empty: each point is a cell of its own (VTK_VERTEX). The type
     * and count are the same in every rank's piece, also in one without
     * points. */
    std::uint8_t              cell_type       = 1;
    unsigned int              points_per_cell = 1;
    std::vector<std::int64_t> connectivity;

  private:
    /** Call @p block(data, n_bytes) for each appended block in file order:
     * the arrays, the points, the cells' connectivity, offsets and
     * types. */
    template <typename Block>
    void
    for_each_block(const Block &block) const;

    /** The file up to its appended data, from the blocks' sizes in it. */
    std::string
    header_xml(const std::vector<std::size_t> &file_bytes,
               const bool                      zlib) const;
  };

  /** This rank's piece <base>.<rank>.vtu of @p cloud in @p directory and,
   * on rank 0 of @p n_ranks, the record <base>.pvtu that lists every
   * rank's piece; returns the record's name. */
  std::string
  write_vtu_pieces(const VtuPointCloud &cloud,
                   const std::string   &directory,
                   const std::string   &base,
                   const unsigned int   rank,
                   const unsigned int   n_ranks,
                   const bool           zlib);
} // namespace dealmpm
