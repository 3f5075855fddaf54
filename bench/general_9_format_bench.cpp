// wtc_bench_format: the recorder's number formatting, std::to_chars
// (general, precision 9) against sim::formatGeneral9 (the same bytes), on
// the same numbers in the same run. Two sets: a random mix of the
// magnitudes the series hold (log-uniform 1e-12..1e6, both signs, one in
// ten a multiple of the 5 ms step as the time column is), and, when CSV
// files are named, every number in them (a recorded run's series):
//   build/bench/wtc_bench_format [benchmark flags] [run/bodies.csv ...]
// items_per_second is numbers a second; ns a number = 1e9 / it.
#include <benchmark/benchmark.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "sim/general_9_format.hpp"

namespace {

constexpr int kMixCount = 1 << 16;  // numbers in the random mix
constexpr double kStep = 0.005;     // s, the time column's spacing

std::vector<double> randomMix() {
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> decade(-12.0, 6.0);
  std::vector<double> numbers;
  for (int i = 0; i < kMixCount; ++i) {
    const double magnitude = std::pow(10.0, decade(random));
    numbers.push_back(i % 10 == 0 ? i * kStep : (i % 2 == 0 ? magnitude : -magnitude));
  }
  return numbers;
}

// Every field of every row after the header that parses as a number.
std::vector<double> csvNumbers(int count, char** paths) {
  std::vector<double> numbers;
  for (int i = 0; i < count; ++i) {
    std::ifstream in(paths[i]);
    if (!in) {
      std::cerr << "wtc_bench_format: cannot read " << paths[i] << "\n";
      std::exit(2);
    }
    std::string line;
    std::getline(in, line);  // the header
    while (std::getline(in, line)) {
      std::istringstream row(line);
      std::string field;
      while (std::getline(row, field, ',')) {
        double v = 0.0;
        const auto r = std::from_chars(field.data(), field.data() + field.size(), v);
        if (r.ec == std::errc()) numbers.push_back(v);
      }
    }
  }
  return numbers;
}

void toChars(benchmark::State& state, const std::vector<double>& numbers) {
  char text[wtc::sim::kGeneral9Chars];
  for (auto _ : state) {
    for (const double v : numbers) {
      char* end = std::to_chars(text, text + sizeof text, v, std::chars_format::general, 9).ptr;
      benchmark::DoNotOptimize(end);
      benchmark::ClobberMemory();
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(numbers.size()));
}

void formatGeneral9(benchmark::State& state, const std::vector<double>& numbers) {
  char text[wtc::sim::kGeneral9Chars];
  for (auto _ : state) {
    for (const double v : numbers) {
      char* end = wtc::sim::formatGeneral9(v, text);
      benchmark::DoNotOptimize(end);
      benchmark::ClobberMemory();
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(numbers.size()));
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  static const std::vector<double> mix = randomMix();
  static const std::vector<double> series = csvNumbers(argc - 1, argv + 1);
  benchmark::RegisterBenchmark("ToChars/mix", toChars, mix);
  benchmark::RegisterBenchmark("FormatGeneral9/mix", formatGeneral9, mix);
  if (!series.empty()) {
    benchmark::RegisterBenchmark("ToChars/series", toChars, series);
    benchmark::RegisterBenchmark("FormatGeneral9/series", formatGeneral9, series);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
