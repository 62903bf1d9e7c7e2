// SPDX-License-Identifier: MIT
// genomes/tuned.toml: every tuned genome shipped in genomes/, with the evolve config in
// configs/evolve/ that made it and the run.json that run wrote, so that each can be checked
// (its values are what the run chose) and re-run against the default on fresh seeds.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace swarmpath::evolve {

struct ShippedGenome {
  std::string params;              ///< the genome (resolved path)
  std::string config;              ///< its evolve config
  std::string run;                 ///< its run.json
  std::optional<int> front_point;  ///< a multi-objective run: which point of the front it is
};

struct GenomeManifest {
  std::string file;
  std::string against;  ///< the default genome it must beat (resolved path)
  std::vector<ShippedGenome> genomes;
};

/// Reads the manifest; paths are taken from its folder. ConfigError (file:line: key) when a file
/// is missing.
GenomeManifest load_genome_manifest(const std::string& path);

/// Why a genome file disagrees with what its run chose ("" when it agrees): each tuned parameter
/// of run.json's best (or front point) against the genome file's value.
std::string genome_mismatch(const ShippedGenome& g);

/// The config hash run.json recorded (the config and its inputs as they were when it ran).
std::string recorded_config_hash(const ShippedGenome& g);

}  // namespace swarmpath::evolve
