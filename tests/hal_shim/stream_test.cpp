// stream_test.cpp - hal_stream: types, full/empty, counters, order, volume, two-thread SPSC,
// and a stream written by a loaded component's realtime function.
#include <atomic>
#include <climits>
#include <cstring>
#include <thread>

#include "hal.h"
#include "hal_fixture.hpp"

class StreamTest : public Hal {
 protected:
  void SetUp() override {
    Hal::SetUp();
    writer = hal_init("writer");
    reader = hal_init("reader");
    ASSERT_GT(writer, 0);
    ASSERT_GT(reader, 0);
  }
  int writer = 0, reader = 0;
};

TEST_F(StreamTest, CreateAndAttachAgreeOnElementTypes) {
  hal_stream_t w, r, any;
  ASSERT_EQ(hal_stream_create(&w, writer, 1001, 8, "fbsu"), 0);
  ASSERT_EQ(hal_stream_attach(&r, reader, 1001, "FBSU"), 0);
  ASSERT_EQ(hal_stream_attach(&any, reader, 1001, nullptr), 0);
  EXPECT_EQ(hal_stream_element_count(&r), 4);
  EXPECT_EQ(hal_stream_element_type(&r, 0), HAL_FLOAT);
  EXPECT_EQ(hal_stream_element_type(&r, 1), HAL_BIT);
  EXPECT_EQ(hal_stream_element_type(&r, 2), HAL_S32);
  EXPECT_EQ(hal_stream_element_type(&any, 3), HAL_U32);
  EXPECT_EQ(hal_stream_element_type(&r, 4), HAL_TYPE_UNSPECIFIED);
  EXPECT_EQ(hal_stream_maxdepth(&r), 8);
  hal_stream_detach(&any);
  hal_stream_detach(&r);
  hal_stream_destroy(&w);
  EXPECT_EQ(w.fifo, nullptr);
}

TEST_F(StreamTest, AttachAndCreateErrorsAreExplained) {
  hal_stream_t s;
  EXPECT_EQ(hal_stream_attach(&s, reader, 2002, "f"), -EINVAL);
  EXPECT_NE(hs::last_error().find("no stream with key 2002"), std::string::npos);
  hal_stream_t w;
  ASSERT_EQ(hal_stream_create(&w, writer, 2002, 4, "ff"), 0);
  EXPECT_EQ(hal_stream_attach(&s, reader, 2002, "fb"), -EINVAL);
  EXPECT_NE(hs::last_error().find("element 1 is float, 'fb' asks for bit"), std::string::npos);
  EXPECT_EQ(hal_stream_attach(&s, reader, 2002, "f"), -EINVAL);
  EXPECT_NE(hs::last_error().find("has 2 elements"), std::string::npos);
  EXPECT_EQ(hal_stream_create(&s, writer, 2002, 4, "ff"), -EEXIST);
  EXPECT_EQ(hal_stream_create(&s, writer, 2003, 4, "fx"), -EINVAL);
  EXPECT_NE(hs::last_error().find("unknown type 'x'"), std::string::npos);
  EXPECT_EQ(hal_stream_create(&s, writer, 2003, 4, "ffffffffffffffffffffff"), -EINVAL);
  EXPECT_NE(hs::last_error().find("more than 21"), std::string::npos);
  EXPECT_EQ(hal_stream_create(&s, writer, 2003, 4, ""), -EINVAL);
  EXPECT_EQ(hal_stream_create(&s, writer, 2003, 1, "f"), -EINVAL);
  hal_stream_destroy(&w);
}

TEST_F(StreamTest, FullAndEmptyAreCountedAsOverrunsAndUnderruns) {
  hal_stream_t w, r;
  ASSERT_EQ(hal_stream_create(&w, writer, 3003, 4, "s"), 0);
  ASSERT_EQ(hal_stream_attach(&r, reader, 3003, "s"), 0);
  hal_stream_data d[1];
  EXPECT_FALSE(hal_stream_readable(&r));
  EXPECT_EQ(hal_stream_read(&r, d, nullptr), -ENOSPC);
  EXPECT_EQ(hal_stream_num_underruns(&r), 1);
  for (int i = 0; i < 3; ++i) {  // depth 4 holds 3 records
    EXPECT_TRUE(hal_stream_writable(&w));
    d[0].s = i;
    EXPECT_EQ(hal_stream_write(&w, d), 0);
    EXPECT_EQ(hal_stream_depth(&r), i + 1);
  }
  EXPECT_FALSE(hal_stream_writable(&w));
  EXPECT_EQ(hal_stream_write(&w, d), -ENOSPC);
  EXPECT_EQ(hal_stream_write(&w, d), -ENOSPC);
  EXPECT_EQ(hal_stream_num_overruns(&r), 2);
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(hal_stream_read(&r, d, nullptr), 0);
    EXPECT_EQ(d[0].s, i);
  }
  EXPECT_EQ(hal_stream_depth(&r), 0);
  EXPECT_EQ(hal_stream_read(&r, d, nullptr), -ENOSPC);
  EXPECT_EQ(hal_stream_num_underruns(&w), 2);
  hal_stream_detach(&r);
  hal_stream_destroy(&w);
}

TEST_F(StreamTest, EveryElementTypeRoundTrips) {
  hal_stream_t w, r;
  ASSERT_EQ(hal_stream_create(&w, writer, 4004, 4, "fbsuf"), 0);
  ASSERT_EQ(hal_stream_attach(&r, reader, 4004, "fbsuf"), 0);
  hal_stream_data in[5], out[5];
  in[0].f = -1.5e-300;
  in[1].b = true;
  in[2].s = INT32_MIN;
  in[3].u = UINT32_MAX;
  in[4].f = 0.1;
  ASSERT_EQ(hal_stream_write(&w, in), 0);
  unsigned sample = 0;
  ASSERT_EQ(hal_stream_read(&r, out, &sample), 0);
  EXPECT_EQ(out[0].f, -1.5e-300);
  EXPECT_TRUE(out[1].b);
  EXPECT_EQ(out[2].s, INT32_MIN);
  EXPECT_EQ(out[3].u, UINT32_MAX);
  EXPECT_EQ(out[4].f, 0.1);
  EXPECT_EQ(sample, 1u);
  hal_stream_detach(&r);
  hal_stream_destroy(&w);
}

TEST_F(StreamTest, AMillionRecordsInOrderWithConsecutiveSampleNumbers) {
  hal_stream_t w, r;
  ASSERT_EQ(hal_stream_create(&w, writer, 5005, 1024, "uf"), 0);
  ASSERT_EQ(hal_stream_attach(&r, reader, 5005, "uf"), 0);
  constexpr unsigned kTotal = 1000000;
  unsigned written = 0, read = 0, bad = 0;
  hal_stream_data d[2];
  while (read < kTotal) {
    while (written < kTotal && hal_stream_writable(&w)) {
      d[0].u = written;
      d[1].f = written * 0.25;
      ASSERT_EQ(hal_stream_write(&w, d), 0);
      ++written;
    }
    unsigned sample = 0;
    while (hal_stream_read(&r, d, &sample) == 0) {
      if (d[0].u != read || d[1].f != read * 0.25 || sample != read + 1) ++bad;
      ++read;
    }
  }
  EXPECT_EQ(bad, 0u);
  EXPECT_EQ(read, kTotal);
  EXPECT_EQ(hal_stream_num_overruns(&w), 0);
  hal_stream_detach(&r);
  hal_stream_destroy(&w);
}

TEST_F(StreamTest, TwoThreadsLoseNothingAndDuplicateNothing) {
  hal_stream_t w, r;
  ASSERT_EQ(hal_stream_create(&w, writer, 6006, 256, "usb"), 0);
  ASSERT_EQ(hal_stream_attach(&r, reader, 6006, "usb"), 0);
  constexpr unsigned kTotal = 2000000;
  std::atomic<unsigned> full{0};
  std::thread producer([&] {
    hal_stream_data d[3];
    for (unsigned i = 0; i < kTotal;) {
      d[0].u = i;
      d[1].s = -static_cast<int>(i);
      d[2].b = (i & 1) != 0;
      if (hal_stream_write(&w, d) == 0) ++i;
      else full.fetch_add(1, std::memory_order_relaxed), std::this_thread::yield();
    }
  });
  unsigned next = 0, bad = 0, empty = 0;
  hal_stream_data d[3];
  while (next < kTotal) {
    unsigned sample = 0;
    if (hal_stream_read(&r, d, &sample) != 0) {
      ++empty;
      std::this_thread::yield();
      continue;
    }
    if (d[0].u != next || d[1].s != -static_cast<int>(next) || d[2].b != ((next & 1) != 0) ||
        sample != next + 1)
      ++bad;
    ++next;
  }
  producer.join();
  EXPECT_EQ(bad, 0u);
  EXPECT_EQ(next, kTotal);
  EXPECT_FALSE(hal_stream_readable(&r));
  EXPECT_EQ(static_cast<unsigned>(hal_stream_num_overruns(&r)), full.load());
  EXPECT_EQ(static_cast<unsigned>(hal_stream_num_underruns(&r)), empty);
  hal_stream_detach(&r);
  hal_stream_destroy(&w);
}

TEST_F(StreamTest, StreamOutlivesItsCreatorUntilTheLastDetach) {
  hal_stream_t w, r;
  ASSERT_EQ(hal_stream_create(&w, writer, 7007, 4, "f"), 0);
  ASSERT_EQ(hal_stream_attach(&r, reader, 7007, "f"), 0);
  hal_stream_data d[1];
  d[0].f = 3;
  ASSERT_EQ(hal_stream_write(&w, d), 0);
  hal_stream_destroy(&w);
  ASSERT_EQ(hal_stream_read(&r, d, nullptr), 0);
  EXPECT_EQ(d[0].f, 3.0);
  hal_stream_detach(&r);
  hal_stream_t again;
  EXPECT_EQ(hal_stream_attach(&again, reader, 7007, "f"), -EINVAL);
}

TEST_F(StreamTest, ComponentWritesAStreamFromItsRealtimeFunction) {
  ASSERT_OK(load("counter", {"key=4242"}));
  ASSERT_OK(hs::new_thread("servo", 1000000));
  ASSERT_OK(hs::add_funct("counter.0", "servo"));
  ASSERT_OK(hs::set_value("counter.0.enable", "1"));
  hal_stream_t r;
  ASSERT_EQ(hal_stream_attach(&r, reader, 4242, "fbsu"), 0);
  ASSERT_OK(hs::step(10));
  EXPECT_EQ(hal_stream_depth(&r), 10);
  hal_stream_data d[4];
  for (int i = 1; i <= 10; ++i) {
    unsigned sample = 0;
    ASSERT_EQ(hal_stream_read(&r, d, &sample), 0);
    EXPECT_EQ(d[2].s, i);
    EXPECT_EQ(d[3].u, static_cast<unsigned>(i));
    EXPECT_EQ(d[0].f, i * 0.5);
    EXPECT_TRUE(d[1].b);
    EXPECT_EQ(sample, static_cast<unsigned>(i));
  }
  ASSERT_OK(hs::step(100));  // depth 64 holds 63 records: 37 writes find it full
  EXPECT_EQ(hal_stream_depth(&r), 63);
  EXPECT_EQ(hal_stream_num_overruns(&r), 37);
  hal_stream_detach(&r);
}
