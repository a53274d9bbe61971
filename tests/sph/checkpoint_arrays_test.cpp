// A solver's particle arrays in its checkpoint (sph/checkpoint_arrays.h): a container that has
// gained arrays since the checkpoint was written (water's wall_side, sph/wall_occluders.h)
// restores the stored ones exactly and fills the new ones with zeros; a checkpoint with more
// arrays than the container is refused.
#include "sph/checkpoint_arrays.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "sph/vector.h"
#include "tests/io/scratch_dir.h"

namespace porosph::sph {
namespace {

struct OldParticles {
  std::size_t n_free = 0;
  std::vector<Vec<2>> position;
  std::vector<std::int64_t> id;
  std::size_t size() const { return position.size(); }
  template <class Fn>
  void for_each_array(Fn&& fn) {
    fn(position), fn(id);
  }
};

struct NewParticles {  // OldParticles with two arrays added at the end
  std::size_t n_free = 0;
  std::vector<Vec<2>> position;
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> tag;
  std::vector<Vec<2>> extra;
  std::size_t size() const { return position.size(); }
  template <class Fn>
  void for_each_array(Fn&& fn) {
    fn(position), fn(id), fn(tag), fn(extra);
  }
};

TEST(CheckpointArrays, ArraysAddedSinceTheCheckpointAreZeroFilled) {
  porosph::test::ScratchDir dir;
  const std::string path = dir.file("old.h5");
  OldParticles old;
  old.n_free = 2;
  old.position = {Vec<2>(0.1, 0.2), Vec<2>(0.3, 0.4), Vec<2>(0.5, 0.6)};
  old.id = {7, 8, 9};
  {
    io::CheckpointWriter out(path);
    write_particle_arrays(out, old);
    out.commit();
  }
  NewParticles now;
  now.tag = {5};  // stale contents are replaced
  read_particle_arrays(io::CheckpointReader(path), now);
  EXPECT_EQ(now.n_free, 2u);
  EXPECT_EQ(now.position, old.position);
  EXPECT_EQ(now.id, old.id);
  EXPECT_EQ(now.tag, std::vector<std::int32_t>(3, 0));
  ASSERT_EQ(now.extra.size(), 3u);
  for (const auto& e : now.extra) EXPECT_EQ(e, Vec<2>::Zero());
  // The other way round: a checkpoint of more arrays than the container knows is refused.
  const std::string newer = dir.file("new.h5");
  {
    io::CheckpointWriter out(newer);
    write_particle_arrays(out, now);
    out.commit();
  }
  OldParticles back;
  EXPECT_THROW(read_particle_arrays(io::CheckpointReader(newer), back), std::runtime_error);
}

}  // namespace
}  // namespace porosph::sph
