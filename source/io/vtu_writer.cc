#include <dealmpm/base/errors.h>
#include <dealmpm/io/output_file.h>
#include <dealmpm/io/vtu_writer.h>

#include <cstring>
#include <numeric>
#include <stdexcept>
#include <zlib.h>

namespace dealmpm
{
  namespace
  {
    const char *
    type_name(const VtuType type)
    {
      switch (type)
        {
          case VtuType::Int32:
            return "Int32";
          case VtuType::Int64:
            return "Int64";
          case VtuType::Float32:
            return "Float32";
          case VtuType::Float64:
            return "Float64";
        }
      return "";
    }

    bool
    is_integer(const VtuType type)
    {
      return type == VtuType::Int32 || type == VtuType::Int64;
    }

    std::size_t
    type_size(const VtuType type)
    {
      return (type == VtuType::Int32 || type == VtuType::Float32) ? 4 : 8;
    }

    /** The header both file kinds share; the byte order is the machine's,
     * since the data are its memory as is. */
    std::string
    file_header(const char *type, const bool zlib = false)
    {
      const std::uint16_t one           = 1;
      const bool          little_endian = *reinterpret_cast<const char *>(&one);
      return std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"") + type +
             "\" version=\"1.0\" byte_order=\"" +
             (little_endian ? "LittleEndian" : "BigEndian") +
             "\" header_type=\"UInt64\"" +
             (zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n";
    }

    std::string
    array_attributes(const std::string &name,
                     const VtuType      type,
                     const unsigned int n_components)
    {
      return std::string("type=\"") + type_name(type) + "\" Name=\"" +
             xml_escaped(name) + "\" NumberOfComponents=\"" +
             std::to_string(n_components) + "\"";
    }

    /** The appended blocks' offset attributes, from each block's size in
     * the file (its header included). */
    class AppendedOffsets
    {
    public:
      /** Reserve a block of @p n_bytes in the file; returns its
       * attribute. */
      std::string
      add(const std::size_t n_bytes)
      {
        const std::string attribute =
          " format=\"appended\" offset=\"" + std::to_string(offset) + "\"";
        offset += n_bytes;
        return attribute;
      }

    private:
      std::size_t offset = 0;
    };

    /** A raw block: a UInt64 byte count, then the bytes. */
    void
    write_raw(OutputFile &file, const void *data, const std::uint64_t n_bytes)
    {
      file.write(&n_bytes, sizeof(n_bytes));
      file.write(data, n_bytes);
    }

    /** A zlib block as VTK reads it: the UInt64 header (number of blocks,
     * their uncompressed size, the last one's, each one's compressed size)
     * and the compressed bytes; one block (none for no bytes). */
    std::string
    compressed_block(const void *data, const std::uint64_t n_bytes)
    {
      if (n_bytes == 0)
        return std::string(3 * sizeof(std::uint64_t), '\0');
      uLongf      size = compressBound(n_bytes);
      std::string block(4 * sizeof(std::uint64_t) + size, '\0');
      if (compress2(reinterpret_cast<Bytef *>(
                      &block[4 * sizeof(std::uint64_t)]),
                    &size,
                    static_cast<const Bytef *>(data),
                    n_bytes,
                    Z_BEST_SPEED) != Z_OK)
        throw OutputError("zlib could not compress a particle array");
      const std::uint64_t header[4] = {1, n_bytes, n_bytes, size};
      std::memcpy(&block[0], header, sizeof(header));
      block.resize(sizeof(header) + size);
      return block;
    }

    template <typename To, typename From>
    std::vector<To>
    converted(const std::vector<From> &values)
    {
      return std::vector<To>(values.begin(), values.end());
    }
  } // namespace

  /** Names come from material models, user code among them. */
  std::string
  xml_escaped(const std::string &text)
  {
    std::string out;
    for (const char c : text)
      switch (c)
        {
          case '&':
            out += "&amp;";
            break;
          case '<':
            out += "&lt;";
            break;
          case '>':
            out += "&gt;";
            break;
          case '"':
            out += "&quot;";
            break;
          default:
            out += c;
        }
    return out;
  }

  unsigned int
  VtuPointCloud::add_array(const std::string &name,
                           const VtuType      type,
                           const unsigned int n_components)
  {
    arrays.push_back(VtuArray{name, type, n_components, {}, {}});
    return arrays.size() - 1;
  }

  void
  VtuPointCloud::resize(const std::size_t n_points)
  {
    points.assign(3 * n_points, 0.);
    for (VtuArray &a : arrays)
      if (is_integer(a.type))
        {
          a.integers.assign(n_points * a.n_components, 0);
          a.reals.clear();
        }
      else
        {
          a.reals.assign(n_points * a.n_components, 0.);
          a.integers.clear();
        }
  }

  template <typename Block>
  void
  VtuPointCloud::for_each_block(const Block &block) const
  {
    const auto bytes = [&](const auto &values) {
      block(values.data(), values.size() * sizeof(values[0]));
    };
    for (const VtuArray &a : arrays)
      switch (a.type)
        {
          case VtuType::Int32:
            bytes(converted<std::int32_t>(a.integers));
            break;
          case VtuType::Int64:
            bytes(a.integers);
            break;
          case VtuType::Float32:
            bytes(converted<float>(a.reals));
            break;
          case VtuType::Float64:
            bytes(a.reals);
            break;
        }
    bytes(points);
    // Without connectivity, cell i is the vertex of point i: connectivity
    // i, end offset i + 1, type VTK_VERTEX (1).
    std::vector<std::int64_t> ends(n_cells());
    for (std::size_t c = 0; c < ends.size(); ++c)
      ends[c] = (c + 1) * (connectivity.empty() ? 1 : points_per_cell);
    if (connectivity.empty())
      {
        std::vector<std::int64_t> indices(n_points());
        std::iota(indices.begin(), indices.end(), std::int64_t(0));
        bytes(indices);
      }
    else
      bytes(connectivity);
    bytes(ends);
    bytes(std::vector<std::uint8_t>(n_cells(),
                                    connectivity.empty() ? 1 : cell_type));
  }

  void
  VtuPointCloud::write_vtu(const std::string &path, const bool zlib) const
  {
    const std::size_t n = n_points();
    for (const VtuArray &a : arrays)
      {
        const std::size_t size =
          is_integer(a.type) ? a.integers.size() : a.reals.size();
        if (size != n * a.n_components)
          throw std::logic_error("VTU array '" + a.name +
                                 "' does not have one value per point and "
                                 "component");
      }
    for (const std::int64_t i : connectivity)
      if (i < 0 || static_cast<std::size_t>(i) >= n ||
          connectivity.size() % points_per_cell != 0)
        throw std::logic_error("VTU cells that name no point of the piece");

    // Each block's size in the file: raw, known from the counts; zlib,
    // known once compressed (the compressed blocks are kept until written).
    std::vector<std::string> compressed;
    std::vector<std::size_t> file_bytes;
    if (zlib)
      for_each_block([&](const void *data, const std::size_t n_bytes) {
        compressed.push_back(compressed_block(data, n_bytes));
        file_bytes.push_back(compressed.back().size());
      });
    else
      {
        for (const VtuArray &a : arrays)
          file_bytes.push_back(n * a.n_components * type_size(a.type));
        const std::size_t n_indices =
          connectivity.empty() ? n : connectivity.size();
        file_bytes.push_back(n * 3 * sizeof(double));
        file_bytes.push_back(n_indices * sizeof(std::int64_t));
        file_bytes.push_back(n_cells() * sizeof(std::int64_t));
        file_bytes.push_back(n_cells() * sizeof(std::uint8_t));
        for (std::size_t &b : file_bytes)
          b += sizeof(std::uint64_t);
      }

    OutputFile file(path);
    file.write(header_xml(file_bytes, zlib));
    if (zlib)
      for (const std::string &block : compressed)
        file.write(block);
    else
      for_each_block([&](const void *data, const std::size_t n_bytes) {
        write_raw(file, data, n_bytes);
      });
    file.write("\n  </AppendedData>\n</VTKFile>\n");
    file.commit();
  }

  std::string
  VtuPointCloud::header_xml(const std::vector<std::size_t> &file_bytes,
                            const bool                      zlib) const
  {
    const std::string n    = std::to_string(n_points());
    std::size_t       next = 0;
    AppendedOffsets   blocks;
    const auto  offset = [&] { return blocks.add(file_bytes.at(next++)); };
    std::string xml    = file_header("UnstructuredGrid", zlib);
    xml += "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" + n +
           "\" NumberOfCells=\"" + std::to_string(n_cells()) +
           "\">\n      <PointData>\n";
    for (const VtuArray &a : arrays)
      xml += "        <DataArray " +
             array_attributes(a.name, a.type, a.n_components) + offset() +
             "/>\n";
    xml += "      </PointData>\n      <Points>\n        <DataArray " +
           array_attributes("Points", VtuType::Float64, 3) + offset() +
           "/>\n      </Points>\n      <Cells>\n";
    xml += "        <DataArray type=\"Int64\" Name=\"connectivity\"" +
           offset() + "/>\n";
    xml +=
      "        <DataArray type=\"Int64\" Name=\"offsets\"" + offset() + "/>\n";
    xml +=
      "        <DataArray type=\"UInt8\" Name=\"types\"" + offset() + "/>\n";
    return xml + "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
                 "  <AppendedData encoding=\"raw\">\n_";
  }

  void
  VtuPointCloud::write_pvtu(const std::string              &path,
                            const std::vector<std::string> &pieces) const
  {
    std::string xml = file_header("PUnstructuredGrid");
    xml += "  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPointData>\n";
    for (const VtuArray &a : arrays)
      xml += "      <PDataArray " +
             array_attributes(a.name, a.type, a.n_components) + "/>\n";
    xml += "    </PPointData>\n    <PPoints>\n      <PDataArray " +
           array_attributes("Points", VtuType::Float64, 3) +
           "/>\n    </PPoints>\n";
    for (const std::string &piece : pieces)
      xml += "    <Piece Source=\"" + xml_escaped(piece) + "\"/>\n";
    xml += "  </PUnstructuredGrid>\n</VTKFile>\n";
    OutputFile file(path);
    file.write(xml);
    file.commit();
  }

  std::string
  write_vtu_pieces(const VtuPointCloud &cloud,
                   const std::string   &directory,
                   const std::string   &base,
                   const unsigned int   rank,
                   const unsigned int   n_ranks,
                   const bool           zlib)
  {
    const auto piece = [&](const unsigned int r) {
      return base + "." + std::to_string(r) + ".vtu";
    };
    cloud.write_vtu(directory + "/" + piece(rank), zlib);
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          pieces.push_back(piece(r));
        cloud.write_pvtu(directory + "/" + base + ".pvtu", pieces);
      }
    return base + ".pvtu";
  }
} // namespace dealmpm
