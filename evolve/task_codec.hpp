// SPDX-License-Identifier: MIT
// The wire form of batches and their results between the processes of an MPI job: a batch
// (params, scenarios, tasks) and a run's Metrics as bytes, and back, every double copied bit for
// bit. Every rank runs the same binary, so numbers travel in the machine's own byte order.
// No MPI here: the codec is tested in every build.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "evolve/batch.hpp"
#include "sim/metrics.hpp"
#include "sim/params.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::evolve {

/// Appends numbers and strings to a byte buffer.
class ByteWriter {
 public:
  void u8(std::uint8_t v) { raw(&v, sizeof v); }

  void u32(std::uint32_t v) { raw(&v, sizeof v); }

  void u64(std::uint64_t v) { raw(&v, sizeof v); }

  void i64(std::int64_t v) { raw(&v, sizeof v); }

  void f64(double v) { raw(&v, sizeof v); }

  void text(const std::string& s);

  const std::vector<char>& bytes() const { return bytes_; }

  std::vector<char> take() { return std::move(bytes_); }

 private:
  void raw(const void* p, std::size_t n);
  std::vector<char> bytes_;
};

/// Reads what a ByteWriter wrote, in the same order; std::runtime_error when the bytes run out.
class ByteReader {
 public:
  explicit ByteReader(std::span<const char> bytes) : bytes_(bytes) {}

  std::uint8_t u8() { return get<std::uint8_t>(); }

  std::uint32_t u32() { return get<std::uint32_t>(); }

  std::uint64_t u64() { return get<std::uint64_t>(); }

  std::int64_t i64() { return get<std::int64_t>(); }

  double f64() { return get<double>(); }

  std::string text();

  bool at_end() const { return pos_ == bytes_.size(); }

 private:
  template <typename T>
  T get() {
    T v;
    raw(&v, sizeof v);
    return v;
  }

  void raw(void* p, std::size_t n);
  std::span<const char> bytes_;
  std::size_t pos_ = 0;
};

void write_scenario(ByteWriter& w, const sim::Scenario& s);
sim::Scenario read_scenario(ByteReader& r);

/// Every parameter of sim::param_table() (all a params file or a genome can set).
void write_params(ByteWriter& w, const sim::Params& p);
sim::Params read_params(ByteReader& r);

void write_metrics(ByteWriter& w, const sim::Metrics& m);
sim::Metrics read_metrics(ByteReader& r);

void write_batch(ByteWriter& w, const SimBatch& b);
SimBatch read_batch(ByteReader& r);

}  // namespace swarmpath::evolve
