// rollwear plot: PNG pictures of a wear run's output folder, drawn by gnuplot.
//
// Reads (columns found by their header names, so added columns do not matter):
//   summary.csv                        revolutions, max_depth_m, p0_Pa; "# case: NAME" names the case
//   snapshots/snapshot_KKKK_BODY.csv   y_m, z_original_m, z_m, depth_m[, damage]; "# revolutions: R"
//   report.txt                         only "case: NAME", when summary.csv has no "# case:" line
// Writes into OUTPUT_DIR/plots/ (each 1000 x 650, pngcairo, else gnuplot's png terminal):
//   depth.png                 the maximum wear depth (µm) against revolutions
//   pressure.png              the peak pressure p0 (MPa) against revolutions
//   profile_BODY.png          per worn body: the profile at each snapshot over the original, z (mm,
//                             axis pointing down into the material) against y (mm)
//   depth_profile_BODY.png    per worn body: the wear depth (µm, axis pointing down) against y (mm)
//   damage_profile_BODY.png   a fatigue run's reference body (its snapshots have the damage column,
//                             docs/fatigue.md): the Miner damage against y (mm) at each snapshot, the line damage 1
// A sweep's output folder (rollwear sweep: results.csv and sweep.txt, docs/sweeps.md) instead gets
//   life_vs_KEY.png           the life (log) against each varied key (dots every case with status ok, the
//                             lives at the budget marked as lower bounds; on a product grid of more than one
//                             axis, a line through the base case's values of the other keys)
//   life_distribution.png     random sampling only: the lives' empirical distribution (i/n) and the
//                             Kaplan-Meier estimate with the budget's lives censored, B10 and B50 marked
// A contact sweep's folder (its results.csv has the contact's columns a_m ... stick_fraction, no life) gets
//   contact_vs_KEY.png        the semi-axes, the peak pressure, the creep forces and the dissipated power
//                             against each varied key (dots every case; on a product grid of more than one
//                             axis, lines through the base case's values of the other keys)
// Cases whose status is not ok are left out (and counted in the titles).
// A cam revolution's folder (rollwear cam: revolution.csv alone) of a case with cam.lubricant or cam.thermal gets, and
// a cam life's folder (rollwear run) whose dissipation.csv has those columns gets too,
//   cam_film.png              h_min and h_c (µm) and λ, and the flash temperature (K), over the cam angle
// A contact's folder (rollwear contact: subsurface_section.csv and strips.csv) instead gets
//   subsurface_body1.png, subsurface_body2.png   von Mises and Tresca's (s1 - s3)/2 (MPa) on the x-z section
//                             through the most loaded cell, depth pointing down (docs/subsurface.md)
// gnuplot runs once on a temporary script (plots/plot.gp.tmp.<pid>); every PNG is drawn to
// PNG + ".tmp.<pid>" and renamed only when gnuplot has succeeded, so a failure leaves no torn PNG and
// no temporary file.
#pragma once

#include <ostream>
#include <string>

// Draws the pictures of output_dir and returns the process's exit status: 0 when every picture was
// drawn; 2 bad input (no folder, no or a malformed summary.csv or snapshot: the file and line named;
// no snapshot at all: depth.png and pressure.png are still drawn); 1 any other failure (gnuplot not
// installed, or failing: its messages quoted; a file that cannot be written). Prints the PNGs written,
// one path a line, on stdout; a failure is one line on stderr starting with "rollwear plot: ".
// Throws nothing.
int plot_command(const std::string& output_dir);

// The same with the streams given (for the tests).
int plot_command(const std::string& output_dir, std::ostream& out, std::ostream& err);
