#include "run_log.h"

#include <deal.II/base/mpi.h>

#include <dealmpm/base/scene_reader.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <streambuf>

namespace dealmpm
{
  namespace
  {
    /** A stream buffer that passes everything on to @p screen and a copy to
     * @p file. */
    class TeeBuffer : public std::streambuf
    {
    public:
      TeeBuffer(std::streambuf *screen, std::streambuf *file)
        : screen(screen)
        , file(file)
      {}

    protected:
      int
      overflow(int c) override
      {
        if (c == traits_type::eof())
          return traits_type::not_eof(c);
        file->sputc(traits_type::to_char_type(c));
        return screen->sputc(traits_type::to_char_type(c));
      }

      std::streamsize
      xsputn(const char *text, std::streamsize n) override
      {
        file->sputn(text, n);
        return screen->sputn(text, n);
      }

      int
      sync() override
      {
        file->pubsync();
        return screen->pubsync();
      }

    private:
      std::streambuf *screen;
      std::streambuf *file;
    };

    /** run.log and the buffers that copy std::cout and std::cerr into it;
     * puts the streams' own buffers back when the program ends. */
    struct RunLog
    {
      std::filebuf               file;
      std::streambuf            *out = nullptr;
      std::streambuf            *err = nullptr;
      std::unique_ptr<TeeBuffer> out_tee, err_tee;

      ~RunLog()
      {
        if (out != nullptr)
          {
            std::cout.flush();
            std::cerr.flush();
            std::cout.rdbuf(out);
            std::cerr.rdbuf(err);
          }
      }
    };

    RunLog run_log;

    void
    write_scene(const ParameterHandler         &prm,
                const std::string              &path,
                const std::string              &scene_file,
                const std::vector<std::string> &overrides)
    {
      std::ofstream out(path);
      if (!out)
        return;
      out << scene_as_run_mark << " (every entry, defaults included)\n"
          << "# scene: " << scene_file << "\n";
      for (const std::string &item : overrides)
        out << "# override: -s '" << quote_value(item) << "'\n";
      out << "# run it again with: dealmpm " << path << "\n\n";
      prm.print_parameters(out,
                           ParameterHandler::PRM | ParameterHandler::Short);
    }
  } // namespace

  void
  start_run_files(const ParameterHandler         &prm,
                  const std::string              &folder,
                  const std::string              &scene_file,
                  const std::vector<std::string> &overrides,
                  const bool                      resumed)
  {
    namespace fs = std::filesystem;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0 ||
        run_log.out != nullptr)
      return;
    // A folder that cannot be made is the output writer's to report, on
    // every rank at once (an error here, on rank 0 alone, would leave the
    // others waiting).
    std::error_code error;
    fs::create_directories(folder, error);
    if (!fs::is_directory(folder, error))
      return;
    const std::string scene = folder + "/run.prm";
    if (!fs::equivalent(scene, scene_file, error))
      try
        {
          write_scene(prm, scene, scene_file, overrides);
        }
      catch (const std::exception &)
        {
          // A full disk: the output writer says so at its first file.
        }
    const auto mode = resumed ? std::ios::out | std::ios::app : std::ios::out;
    if (run_log.file.open(folder + "/run.log", mode) == nullptr)
      return;
    if (resumed)
      run_log.file.sputn("\n", 1);
    run_log.out_tee =
      std::make_unique<TeeBuffer>(std::cout.rdbuf(), &run_log.file);
    run_log.err_tee =
      std::make_unique<TeeBuffer>(std::cerr.rdbuf(), &run_log.file);
    run_log.out = std::cout.rdbuf(run_log.out_tee.get());
    run_log.err = std::cerr.rdbuf(run_log.err_tee.get());
  }
} // namespace dealmpm
