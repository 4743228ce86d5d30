// The run's histories as charts (io/chart): the energy account of DIR/history.csv and the
// monitors' displacements of DIR/monitors.csv against time, read as docs/output-format.md
// defines them. Part of the run's pictures (io/run_pictures, dda plot).
#pragma once

#include <filesystem>

#include "io/chart.hpp"

namespace dda {

// The energy account against time, from the first row of each step: the terms that are not
// zero throughout (potential as its change since the start) and the remainder. Throws
// std::runtime_error naming the file when it cannot be read, lacks a column or holds a
// field that is not a number.
ChartOptions energy_chart(const std::filesystem::path& history_csv);

// Each monitor's displacement components ux (thick) and uy (thin) against time.
ChartOptions monitors_chart(const std::filesystem::path& monitors_csv);

}  // namespace dda
