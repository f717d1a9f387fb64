#include <dealmpm/core/run_state.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

namespace dealmpm
{
  void
  RunState::save(std::ostream &out) const
  {
    boost::archive::text_oarchive archive(out);
    archive << *this;
  }

  void
  RunState::load(std::istream &in)
  {
    boost::archive::text_iarchive archive(in);
    archive >> *this;
  }
} // namespace dealmpm
