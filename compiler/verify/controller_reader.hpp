#pragma once
// Reading a controller file, NAME.controller.json (`oasisc compile` of a continuous model with
// an `objective`; docs/guarantees.md, "The output"), for `oasisc verify`:
//
//   {"format": "oasis-controller", "version": 1, "model": NAME, "variables": [NAME, ...],
//    "grid": [{"cells": n, "breaks": [t_0, ..., t_n]}, ...],
//    "inputs": [{"name": NAME, "values": [v, ...]}, ...],
//    "actions": [{"action": NAME, "inputs": [v, ...]}, ...],
//    "objective": {"kind": "safety" | "reach-avoid", "steps": N | null,
//                  "exactly_at_step": BOOL},
//    "lower": [p, ...], "upper": [p, ...],
//    "controller": [a, ...] | [[a, ...], ...]}
//
// Only the file's shape is checked here (each key present, each value of its type, sizes
// consistent within the file); whether it matches the spec is controller_check.hpp's business.
// Errors name the JSON path ("grid[1].breaks[3] is a string, not a number"). The per-cell
// arrays go straight into vectors while the text is parsed, so a large grid's arrays never
// exist as a JSON tree.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace oasis::verify {

struct ControllerAxis {
  std::uint64_t cells = 0;
  std::vector<double> breaks;
};

struct ControllerInput {
  std::string name;
  std::vector<double> values;
};

struct ControllerAction {
  std::string action;
  std::vector<double> inputs;
};

struct ControllerObjective {
  std::string kind;                    // "safety" or "reach-avoid" (any string here)
  std::optional<std::uint64_t> steps;  // null: unbounded
  bool exactly_at_step = false;
};

struct ControllerFile {
  std::string model;
  std::vector<std::string> variables;
  std::vector<ControllerAxis> grid;
  std::vector<ControllerInput> inputs;
  std::vector<ControllerAction> actions;
  ControllerObjective objective;
  std::vector<double> lower;
  std::vector<double> upper;
  // Bounded objectives: one array per step (`per_step`); unbounded: one array.
  std::vector<std::vector<std::uint64_t>> controller;
  bool per_step = false;
};

// True when `path` ends in ".controller.json", or is a JSON object whose "format" is
// "oasis-controller". A file that cannot be read is not one (verify's other readers say what
// is wrong with it).
bool is_controller_file(const std::string& path, std::size_t max_bytes);

// Reads `path`. On failure (also a file larger than `max_bytes`) returns nullopt and sets
// `error` to one sentence (without the path).
std::optional<ControllerFile> read_controller_file(const std::string& path, std::size_t max_bytes,
                                                   std::string& error);
// The same on the file's text.
std::optional<ControllerFile> parse_controller_file(std::string_view text, std::string& error);

}  // namespace oasis::verify
