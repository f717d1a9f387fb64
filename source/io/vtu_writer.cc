#include <dealmpm/io/output_file.h>
#include <dealmpm/io/vtu_writer.h>

#include <numeric>
#include <stdexcept>

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
    file_header(const char *type)
    {
      const std::uint16_t one           = 1;
      const bool          little_endian = *reinterpret_cast<const char *>(&one);
      return std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"") + type +
             "\" version=\"1.0\" byte_order=\"" +
             (little_endian ? "LittleEndian" : "BigEndian") +
             "\" header_type=\"UInt64\">\n";
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

    /** Appended blocks: a UInt64 byte count, then the bytes. */
    class AppendedBlocks
    {
    public:
      /** Reserve a block and return the offset attribute for it. */
      std::string
      add(const std::size_t n_bytes)
      {
        const std::string attribute =
          " format=\"appended\" offset=\"" + std::to_string(offset) + "\"";
        offset += sizeof(std::uint64_t) + n_bytes;
        return attribute;
      }

      template <typename T>
      static void
      write(OutputFile &file, const std::vector<T> &values)
      {
        const std::uint64_t n_bytes = values.size() * sizeof(T);
        file.write(&n_bytes, sizeof(n_bytes));
        file.write(values.data(), n_bytes);
      }

    private:
      std::size_t offset = 0;
    };

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

  void
  VtuPointCloud::write_vtu(const std::string &path) const
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

    AppendedBlocks blocks;
    std::string    xml = file_header("UnstructuredGrid");
    xml += "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" +
           std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(n) +
           "\">\n      <PointData>\n";
    for (const VtuArray &a : arrays)
      xml += "        <DataArray " +
             array_attributes(a.name, a.type, a.n_components) +
             blocks.add(n * a.n_components * type_size(a.type)) + "/>\n";
    xml += "      </PointData>\n      <Points>\n        <DataArray " +
           array_attributes("Points", VtuType::Float64, 3) +
           blocks.add(3 * n * sizeof(double)) +
           "/>\n      </Points>\n      <Cells>\n";
    xml += "        <DataArray type=\"Int64\" Name=\"connectivity\"" +
           blocks.add(n * sizeof(std::int64_t)) + "/>\n";
    xml += "        <DataArray type=\"Int64\" Name=\"offsets\"" +
           blocks.add(n * sizeof(std::int64_t)) + "/>\n";
    xml += "        <DataArray type=\"UInt8\" Name=\"types\"" +
           blocks.add(n * sizeof(std::uint8_t)) + "/>\n";
    xml += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
           "  <AppendedData encoding=\"raw\">\n_";

    OutputFile file(path);
    file.write(xml);
    for (const VtuArray &a : arrays)
      switch (a.type)
        {
          case VtuType::Int32:
            AppendedBlocks::write(file, converted<std::int32_t>(a.integers));
            break;
          case VtuType::Int64:
            AppendedBlocks::write(file, a.integers);
            break;
          case VtuType::Float32:
            AppendedBlocks::write(file, converted<float>(a.reals));
            break;
          case VtuType::Float64:
            AppendedBlocks::write(file, a.reals);
            break;
        }
    AppendedBlocks::write(file, points);
    // Cell i is the vertex of point i: connectivity i, end offset i + 1,
    // type VTK_VERTEX (1).
    std::vector<std::int64_t> indices(n);
    std::iota(indices.begin(), indices.end(), std::int64_t(0));
    AppendedBlocks::write(file, indices);
    std::iota(indices.begin(), indices.end(), std::int64_t(1));
    AppendedBlocks::write(file, indices);
    AppendedBlocks::write(file, std::vector<std::uint8_t>(n, 1));
    file.write("\n  </AppendedData>\n</VTKFile>\n");
    file.commit();
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
} // namespace dealmpm
