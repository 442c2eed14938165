#!/usr/bin/env python3
"""Plants deliberate bugs, one at a time, and checks that the suite catches each.

usage: run_mutations.py [WORK_DIRECTORY] [--only REGEX] [--sample N [--turn K]]
       run_mutations.py --in-place [--only REGEX] [--sample N [--turn K]]
       run_mutations.py --check-texts
Copies the tracked sources of this repository into WORK_DIRECTORY/src
(default /tmp/nsm-mutations), builds them once and checks that the unmutated
suite passes; with --in-place (CI, on a disposable clone) it mutates this
tree itself and rebuilds build/, which ./test.sh has just built and tested.
Then for each mutation: applies it, rebuilds nsm-bar and the unit tests,
runs CTest, and restores the file. Fails unless every mutation makes at least
one test fail. --only runs the mutations whose name matches REGEX; --sample N
runs an N-th of them, those whose index is the commit count (or --turn K)
modulo N, so that N consecutive turns run every one. Not part of CTest, but for
--check-texts (CTest mutations.texts): each mutation's text occurs exactly once
in its file (whitespace matching any whitespace), so that a change of the code
it plants into is noticed by the suite, not by the next mutation run.
"""
import argparse
import signal
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# (name, file, text, replacement): the text must occur exactly once, its
# whitespace matching any whitespace (matches()), so that re-indenting or
# re-wrapping the code it plants into keeps the mutation.
MUTATIONS = [
    ("forced response: the damping's sign flipped", "source/model/damped_receptance.cc",
     "r = residues[j], a = eigenvalues[j] - sigma, b = damping[j] * omega;",
     "r = residues[j], a = eigenvalues[j] - sigma, b = -damping[j] * omega;"),
    ("forced response: the drive as a sine", "source/harmonic_balance/forced_harmonic_balance.cc",
     "u[2] += f * h.real();\n    u[1] -= f * h.imag();", "u[1] += f * h.real();\n    u[2] += f * h.imag();"),
    ("uniform load: the cross weights' sign flipped", "source/model/load_modes.cc",
     "result.cross.push_back(phi[p.contact_row] * b);", "result.cross.push_back(-phi[p.contact_row] * b);"),
    ("uniform load: the self weights as b_j, not b_j^2", "source/model/load_modes.cc",
     "result.self.push_back(b * b);", "result.self.push_back(std::abs(b));"),
    ("uniform load: the far modes' first order left out", "source/model/damped_receptance.cc",
     "{far[0] + far[1] * omega * omega,", "{far[0] + 0 * far[1] * omega * omega,"),
    ("uniform load: the drive's cross term in the energy left out", "source/harmonic_balance/forced_harmonic_balance.cc",
     "m.energy += 0.25 * (cross * energy.cross + f * f * energy.self);", "m.energy += 0.25 * (f * f * energy.self);"),
    ("uniform load: the drive's own share of its power left out", "source/harmonic_balance/forced_harmonic_balance.cc",
     "- forcing_ * receptance_.drive_self(omega_).imag();", ";"),
    ("uniform load's time integration: the modes driven by r_j", "source/verification/forced_modal_steps.cc",
     "const double r = modes.contact_residues[j], s = receptance.drive_weights()[j];",
     "const double r = modes.contact_residues[j], s = modes.contact_residues[j];"),
    ("Floquet: the wall's slope in the steps' tangents flipped", "include/nsm/model/contact_law.h",
     "return penetrates(u) ? -1 / (response + compliance_) : 0.0;", "return penetrates(u) ? 1 / (response + compliance_) : 0.0;"),
    ("Floquet: the tangents' step without the wall's force's change", "source/verification/forced_modal_steps.cc",
     "advance(d.q[j], d.v[j], d.a[j], dconstant[j] + slope_[j] * df, dt);",
     "advance(d.q[j], d.v[j], d.a[j], dconstant[j], dt);"),
    ("forced response's time integration: the accelerations without the Newmark update's -a",
     "source/verification/forced_modal_steps.cc",
     "const double a_next = 4 / (dt * dt) * (q_next - q - dt * v) - a;",
     "const double a_next = 4 / (dt * dt) * (q_next - q - dt * v);"),
    ("Floquet: the shooting's restart without the wall's force", "source/verification/forced_modal_steps.cc",
     "m.a = m.residue * force_ + m.drive * drive_ - m.damping * m.v - m.eigenvalue * m.q;\n  }\n\n  ForcedModalSteps::Tangent",
     "m.a = m.drive * drive_ - m.damping * m.v - m.eigenvalue * m.q;\n  }\n\n  ForcedModalSteps::Tangent"),
    ("Floquet: a period doubling called a fold", "source/verification/forced_floquet.cc",
     'return m.real() > 0 ? "fold" : "period doubling";', 'return "fold";'),
    ("forced response: steps may retrace the linear response", "source/continuation/forced_response.cc",
     "if (on_linear_response(curve_.points[i], i))", "if (false)"),
    ("result: no note where the branch was traced from grazing outside the range", "source/app/run_result.cc",
     "if (direction * (from - near_end) < 0)", "if (false)"),
    ("forced response: a run that comes back along the curve is not cut", "source/continuation/forced_response.cc",
     "back  = on.back <= retrace_share ? back + 1 : 0;", "back  = 0;"),
    ("forced response: a run that goes round a loop of the curve again is not cut",
     "source/continuation/forced_response.cc",
     "along = on.forward <= retrace_share ? along + 1 : 0;", "along = 0;"),
    ("forced response: a run along the path traced before goes on to Max steps",
     "source/continuation/forced_response.cc", "ended = ends && ends();", "ended = false;"),
    ("forced response: the retrace cut keeps the points after the turn", "source/continuation/forced_response.cc",
     "        curve_.points.resize(turn + 1);\n        return true;", "        curve_.points.resize(found);\n        return true;"),
    ("forced response: the receptance's imaginary part flipped in the sine row",
     "source/harmonic_balance/forced_harmonic_balance.cc",
     "u[2 * k - 1] = gr * b - gi * a;", "u[2 * k - 1] = gr * b + gi * a;"),
    ("forced response: energy per harmonic doubled", "source/harmonic_balance/forced_harmonic_balance.cc",
     "m.energy += 0.25 * size", "m.energy += 0.5 * size"),
    ("forced response: modal damping zeta w_j", "source/scene/damping_parameters.cc",
     "2 * modal_ratio * std::sqrt(eigenvalue)", "modal_ratio * std::sqrt(eigenvalue)"),
    ("forced response: Rayleigh beta on w_j", "source/scene/damping_parameters.cc",
     "rayleigh_beta * eigenvalue", "rayleigh_beta * std::sqrt(eigenvalue)"),
    ("forced response's time integration: the damping's sign flipped", "source/verification/forced_modal_steps.cc",
     "const double rest      = damping * (v + dt / 2 * a)", "const double rest      = -damping * (v + dt / 2 * a)"),
    ("forced response's time integration: the drive as a sine", "source/verification/forced_modal_steps.cc",
     "forcing_ * std::cos(omega_ * double(step_) * dt)", "forcing_ * std::sin(omega_ * double(step_) * dt)"),
    ("forced response: no contact guard", "source/continuation/forced_response.cc",
     "std::abs(contact - last.contact) <= continuation.max_contact_change &&", "true &&"),
    ("forced response: no motion guard", "source/continuation/forced_response.cc",
     "relative_change(displacement, last.displacement) <= continuation.max_solution_change", "true"),
    ("forced response: no restart at a corner", "source/continuation/forced_response.cc",
     "(restart_at_corner() || enter_contact() || enter_at_grazing() || leap(onto_other_motions) ||",
     "(enter_contact() || enter_at_grazing() || leap(onto_other_motions) ||"),
    ("forced response: no leap past a stall", "source/continuation/forced_response.cc",
     "(restart_at_corner() || enter_contact() || enter_at_grazing() || leap(onto_other_motions) ||",
     "(restart_at_corner() || enter_contact() || enter_at_grazing() || false ||"),
    ("forced response: no entry by the contact force's mean", "source/continuation/forced_response.cc",
     "(restart_at_corner() || enter_contact() || enter_at_grazing() || leap(onto_other_motions) ||",
     "(restart_at_corner() || enter_at_grazing() || leap(onto_other_motions) ||"),
    ("forced response: a distributed drive evaluated beyond its modal band", "source/continuation/forced_response.cc",
     "return kind != ForcedSweep::omega || hb.drives_at(v);", "return true;"),
    ("forced response: a leap onto another motion before the trace from the far end",
     "source/continuation/forced_response.cc", "go_on_at_stalls(!from_both_ends);", "go_on_at_stalls(true);"),
    ("forced response: a verdict flipping at one corner named each time", "source/output/forced_response_table.cc",
     "if (!changes.empty() && changes.back().first == at)", "if (false)"),
    ("forced response: no entry at grazing", "source/continuation/forced_response.cc",
     "(restart_at_corner() || enter_contact() || enter_at_grazing() || leap(onto_other_motions) ||",
     "(restart_at_corner() || enter_contact() || leap(onto_other_motions) ||"),
    ("forced response: the grazing impulse at the nearest swing", "source/continuation/forced_response.cc",
     "const double       farthest = std::atan2(u[1], u[2]);", "const double       farthest = std::atan2(u[1], u[2]) + M_PI;"),
    ("forced response: a lag wrapping from pi to -pi taken for phase resonance", "source/output/forced_response_table.cc",
     "a * b > 0 || a == b || std::abs(b - a) > M_PI)", "a * b > 0 || a == b)"),
    ("forced response: points beyond the range's ends written", "source/continuation/forced_response.cc",
     "if (skip || value < low || value > high)", "if (skip)"),
    ("forced response: a curve still climbing at its range's end given a peak", "source/output/forced_response_table.cc",
     "return swept_value(curve, peak) == swept_value(curve, low) || swept_value(curve, peak) == swept_value(curve, high);",
     "return false;"),
    ("forced response: no trace from Omega max where the start at Omega min converged nowhere",
     "source/continuation/forced_response.cc", "if (!curve_.finished && from_both_ends && steps_left() > 0)",
     "if (!curve_.finished && from_both_ends && !curve_.points.empty() && steps_left() > 0)"),
    ("forced response: starts may land on the curve already", "source/continuation/forced_response.cc",
     "bool retraces(const ForcedPoint &next) {", "bool retraces(const ForcedPoint &next) { return false;"),
    ("forced response: dR/dF's sign flipped", "source/harmonic_balance/forced_harmonic_balance.cc",
     "for (double &d : result) d = -d;", "for (double &d : result) d = d;"),
    ("forced response: the fold test's verdict inverted", "source/harmonic_balance/forced_harmonic_balance.cc",
     "lu_determinant_sign(n, jacobian.data(), pivots.data()) > 0", "lu_determinant_sign(n, jacobian.data(), pivots.data()) < 0"),
    ("forced response: the determinant's sign from U's diagonal alone", "source/base/dense_lu.cc",
     "if ((pivots[k] != k) != (lu[k + std::size_t(k) * n] < 0))", "if (lu[k + std::size_t(k) * n] < 0)"),
    ("forced response: fixed-W restarts at Initial step only", "source/continuation/forced_response.cc",
     "distance >= continuation_.min_step; distance /= 2)", "distance >= step; distance /= 2)"),
    ("forced response's verification: a tenth of the steady state's periods", "source/verification/forced_time_verification.cc",
     "std::ceil(std::log(1 / forced_verification_constants::transient_share)",
     "0.1 * std::ceil(std::log(1 / forced_verification_constants::transient_share)"),
    ("study: the force levels scaled against the damping", "source/study/study_combinations.cc",
     "format_value(f * ratio)", "format_value(f / ratio)"),
    ("study: the forced peaks' distance signed", "source/study/study_measures.cc",
     "std::abs(*peak.distance)", "*peak.distance"),
    ("forced response: a stop signal does not end the curves", "source/app/pipeline.cc",
     "forced_left_out_.push_back(\"forced response's curves from F = \" + significant(amplitude, 4) + \" on\"); break;",
     "forced_left_out_.push_back(\"forced response's curves from F = \" + significant(amplitude, 4) + \" on\");"),
    ("harmonic balance's wall at g0 / 2", "source/harmonic_balance/harmonic_balance.cc",
     "force_scale_  = law_.gap() / gamma0_;", "force_scale_  = 0.5 * law_.gap() / gamma0_;"),
    ("harmonic balance's gap doubled", "source/harmonic_balance/harmonic_balance.cc",
     "force_scale_  = law_.gap() / gamma0_;", "force_scale_  = 2 * law_.gap() / gamma0_;"),
    ("the contact law's gap 10 % off", "source/model/contact_law.cc",
     "gap_(contact.gap)", "gap_(1.1 * contact.gap)"),
    ("the compliant wall's energy left out", "include/nsm/model/contact_law.h",
     "return rigid() || !penetrates(u) ? 0.0 : 0.5 * gap_weight_ * gap_at(u) * gap_at(u);", "return 0.0;"),
    ("the compliant wall twice as stiff in the harmonic balance", "source/model/contact_law.cc",
     "contact.alpha : contact.stiffness)", "contact.alpha : 2 * contact.stiffness)"),
    ("the compliant wall's time step with twice its compliance", "include/nsm/model/contact_law.h",
     "gap_at(u) / (response + compliance_)", "gap_at(u) / (response + 2 * compliance_)"),
    ("force sign flipped", "source/model/contact_law.cc",
     "sign_(contact.sign == ForceSign::physical ? 1.0 : -1.0)",
     "sign_(contact.sign == ForceSign::physical ? -1.0 : 1.0)"),
    ("graded layer at the clamp", "source/model/discretisation.cc",
     "sizes[i] = std::pow(params.graded_ratio, i - first + 1);",
     "sizes[params.cells - 1 - i] = std::pow(params.graded_ratio, i - first + 1);"),
    ("energy off by 1 %", "source/harmonic_balance/solution_measures.cc",
     "result.energy = ec[0];", "result.energy = 1.01 * ec[0];"),
    ("one Gram-matrix entry 1 % wrong", "source/harmonic_balance/structured_gram.cc",
     "row[j] = h * (c[j - i] + c[i + j]);", "row[j] = (i == 1 && j == 2 ? 1.01 : 1.0) * h * (c[j - i] + c[i + j]);"),
    ("the Hankel part of the Gram matrix with the wrong sign", "source/harmonic_balance/structured_gram.cc",
     "row[j] = h * (c[i - j] + c[i + j]);", "row[j] = h * (c[i - j] - c[i + j]);"),
    ("the full basis' sine-sine Gram entries with the wrong Hankel sign", "source/harmonic_balance/structured_gram.cc",
     "put(sk, sl, c[d] - c[sum]);", "put(sk, sl, c[d] + c[sum]);"),
    ("the full basis' sine-cosine Gram entries with the Toeplitz part's sign flipped",
     "source/harmonic_balance/structured_gram.cc",
     "put(sk, cl, s[sum] + sgn * s[d]);", "put(sk, cl, s[sum] - sgn * s[d]);"),
    ("the series' chains rotated by one angle too few", "source/harmonic_balance/trigonometric_series.cc",
     "const double step_c = c[lanes - 1] * c1 - s[lanes - 1] * s1;", "const double step_c = c[lanes - 1];"),
    ("the blocked LU's second column skips a row group's update", "source/base/dense_lu.cc",
     "a0[b] -= lp * u0[p], a1[b] -= lp * u1[p];", "a0[b] -= lp * u0[p]; if (b == 0) a1[b] -= lp * u1[p];"),
    ("the energy's spread from its cosines at half weight", "source/harmonic_balance/solution_measures.cc",
     "coefficients[2 * m - 1] = es[m], coefficients[2 * m] = ec[m];",
     "coefficients[2 * m - 1] = es[m], coefficients[2 * m] = 0.5 * ec[m];"),
    ("the series at the samples with the sines' sign flipped", "source/harmonic_balance/series_samples.cc",
     "c[k][1] -= 0.5 * v[i];", "c[k][1] += 0.5 * v[i];"),
    ("the series at the samples with the cosines at full weight", "source/harmonic_balance/series_samples.cc",
     "c[k][0] += 0.5 * v[i];", "c[k][0] += v[i];"),
    ("LOCA's solves keep the factors of a Jacobian that changed", "source/continuation/dense_lu_group.cc",
     "if (factored_ && std::equal(a, a + std::size_t(n) * n, matrix_.begin()))", "if (factored_)"),
    ("the LU's pivot search takes the first row", "source/base/dense_lu.cc",
     "while (std::abs(column[pivot]) != largest)", "while (false)"),
    ("receptance derivative 1 % wrong", "source/model/receptance.cc",
     "value.dgamma_domega2 += term / distance;",
     "value.dgamma_domega2 += 1.01 * term / distance;"),
    ("modal residues without inverse iteration", "source/model/near_modes.cc",
     "for (int step = 0; step < 2; ++step)", "for (int step = 0; step < 0; ++step)"),
    ("far-mode series keeps the near poles", "source/model/near_modes.cc",
     "f -= near.contact_residues[j] / (lambda[j] - s);",
     "f -= 0 * near.contact_residues[j] / (lambda[j] - s);"),
    ("verification's wall at 2 g0", "source/verification/time_verification.cc",
     "    : law_(law)", "    : law_(ContactLaw(ContactParameters{true, 2 * law.gap(), law.gap_weight(), ForceSign::physical}))"),
    ("the time integration's wall pulls the bar", "source/verification/time_verification.cc",
     "        next.add(lambda, contact_response_);", "        next.add(-lambda, contact_response_);"),
    ("the harmonic balance's energy twice too large", "source/harmonic_balance/solution_measures.cc",
     "      result.energy = ec[0];", "      result.energy = 2 * ec[0];"),
    ("verification loses the contact DoF's mass", "source/model/mass_redistribution.cc",
     "removed * std::abs(e->value()) / coupling", "0 * removed * std::abs(e->value()) / coupling"),
    ("Contact mass = redistributed keeps the contact DoF's mass", "source/model/discretisation.cc",
     "if (contact_mass_ == ContactMass::redistributed)", "if (false && contact_mass_ == ContactMass::redistributed)"),
    ("residues without inertia at the contact DoF drop the unpaired zero", "source/model/spectrum.cc",
     "product *= (1 - lambda[j] / mu[k]) / (1 - lambda[j] / pole);",
     "product *= i < lambda.size() ? (1 - lambda[j] / mu[k]) / (1 - lambda[j] / pole) : 1.0;"),
    ("a resumed refinement shoots its kept points again", "source/verification/orbit_refinement.cc",
     "const bool kept = orbits[i].has_value();", "const bool kept = false;"),
    ("exact flow's wall moved in the switch test alone", "source/verification/modal_flow.cc",
     "r.constant = -law_.gap();", "r.constant = -1.01 * law_.gap();"),
    ("exact flow's tangent loses a factor omega", "source/verification/modal_flow.cc",
     "dr_new(j, col) = -r.omega[j] * x * s[j] + y * c[j];", "dr_new(j, col) = -x * s[j] + y * c[j];"),
    ("exact taper reference with the end force's sign flipped", "source/model/exact_references.cc",
     "const double f   = -sign * young_ * section_L_ * k;",
     "const double f   = sign * young_ * section_L_ * k;"),
    ("study: a Backbone omega off the main branch counted empty where it has a value",
     "source/study/study.cc", "empty += text_cell(row, c).empty();", "empty += !text_cell(row, c).empty();"),
    ("a backbone's failure beside forced curves ends the run", "source/app/pipeline.cc",
     "run.harmonic_balance_beside_forcing();", "run.harmonic_balance();"),
    ("forced response: an anti-resonance named a phase resonance", "source/output/forced_response_table.cc",
     "(b - a) * (q.omega - p.omega) < 0)", "(b - a) * (q.omega - p.omega) < -1e300)"),
    ("forced response: a curve cut by Max steps reads as a stall", "source/continuation/forced_response.cc",
     "curve_.out_of_steps = !curve_.whole() && steps_left() == 0;", "curve_.out_of_steps = false;"),
    ("forced response: a curve with no point is no failure", "source/app/pipeline.cc",
     "if (curve.points.empty())\n            record_failure(", "if (curve.points.empty() && false)\n            record_failure("),
    ("study deals each round's row to every rank", "source/study/study.cc",
     "const std::size_t mine = round + rank_;",
     "const std::size_t mine = round;"),
    ("tongues sought below the envelope of the points before", "source/continuation/main_branch.cc",
     "above_envelope(points, direction,", "above_envelope(points, -direction,"),
    ("fine backbone reference with the gap 10 % off", "source/study/study_combinations.cc",
     'set_entry(prm, "Discretisation", "Refinement", "none");',
     'set_entry(prm, "Discretisation", "Refinement", "none");\n    set_entry(prm, "Contact", "Gap", "1.1e-3");'),
    ("forced curve: no second trace from Omega max where the first stopped", "source/continuation/forced_response.cc",
     "if (!curve_.finished && from_both_ends && steps_left() > 0)",
     "if (false)"),
    ("forced curve: two traces never meet", "source/continuation/forced_response.cc",
     "joined_ ? ForcedCurve::Meeting::joined : ForcedCurve::Meeting::none;",
     "ForcedCurve::Meeting::none;"),
    ("forced curve: a trace from Omega max that joins the first trace's path goes on",
     "source/continuation/forced_response.cc",
     "            joined_ = true;\n            curve_.points.resize(end - count.first_run);",
     "            curve_.points.resize(end - count.first_run);"),
    ("forced curve: the join begins at its fifth point", "source/continuation/forced_response.cc",
     "else if (on.first <= retrace_share_most && first > 0)", "else if (false)"),
    ("forced curve: no finer Min step at a stall nothing else goes on from", "source/continuation/forced_response.cc",
     "if (trace_refinements_ == continuation_constants::forced_min_step_refinements)\n          return false;",
     "if (true)\n          return false;"),
    ("forced curve: the points set aside for a finer Min step lost where nothing went on",
     "source/continuation/forced_response.cc",
     "i-- > 0 && curve_.points.size() == set_aside_[i].kept;", "i-- > 0 && false;"),
    ("forced peak: compared whether or not its curve was traced whole", "source/output/forced_response_table.cc",
     "if (!curve.whole())\n        return PeakLeftOut::not_whole;", "if (false)\n        return PeakLeftOut::not_whole;"),
    ("forced peak: a peak never touching the wall compared with the backbone", "source/output/forced_response_table.cc",
     "if (peak.measures.contact_fraction == 0)\n        return PeakLeftOut::linear;",
     "if (false)\n        return PeakLeftOut::linear;"),
    ("forced peak: a peak at the range's end compared with the backbone", "source/output/forced_response_table.cc",
     "if (at_range_end(curve, peak))\n        return PeakLeftOut::at_range_end;",
     "if (false)\n        return PeakLeftOut::at_range_end;"),
    ("forced verification: entries only for the curves a stop signal let it reach", "source/app/pipeline.cc",
     "        for (const ForcedCurve &curve : curves)\n          verifications.emplace_back(curve.points.size());\n        for (std::size_t c = 0; c < curves.size(); ++c)\n          {\n            const ForcedCurve &curve = curves[c];",
     "        for (std::size_t c = 0; c < curves.size(); ++c)\n          {\n            const ForcedCurve &curve = curves[c];\n            verifications.emplace_back(curve.points.size());"),
    ("forced verification: the static point at Omega = 0 integrated", "source/app/pipeline.cc",
     "if (!(curve.points[i].omega > 0))\n                  continue;", "if (false)\n                  continue;"),
    ("gap search: the stretch from the range's near end not searched where the branch enters from outside",
     "source/continuation/gap_filling.cc",
     "context.in_range(backbone.points.front().omega) ? std::nullopt : std::optional<double>(context.near_end);",
     "std::optional<double>();"),
    ("a field solved beside a point placed by rising Omega whatever the direction", "source/continuation/continuation.cc",
     "return index + (direction * (omega - points[index].omega) > 0 ? 1 : 0);",
     "return index + ((omega - points[index].omega) > 0 ? 1 : 0);"),
    ("fields always labelled main", "source/continuation/main_branch.cc",
     "point.branch    = with[at].branch;", "point.branch    = Branch::main;"),
    ("a point labelled alone: the tongue run holding it left unnamed", "source/continuation/main_branch.cc",
     "if (only == every_point || (first <= only && only < end))", "if (only == every_point)"),
    ("a point labelled alone at the backbone's end, not where it lies", "source/continuation/main_branch.cc",
     "const std::size_t          at   = position ? std::min(*position, with.size()) : with.size();",
     "const std::size_t          at   = with.size();"),
    ("gap filling past the gap's far side", "source/continuation/sequential_steps.cc",
     "if (limits && !context.beyond(limits->join_at, omega))", "if (false)"),
    ("gap filling climbs tongues", "source/continuation/sequential_steps.cc",
     "(limits && point.measures.energy > limits->tongue_above)", "false"),
    ("gap filling from the main guesses only", "source/continuation/gap_filling.cc",
     "if (context.beyond(q.omega, gap.first) && context.beyond(gap.second, q.omega))",
     "if (q.branch == Branch::main && context.beyond(q.omega, gap.first) && context.beyond(gap.second, q.omega))"),
    ("gap filling that keeps a tongue landing", "source/continuation/gap_filling.cc",
     "if (point.branch == Branch::main)\n              return true;\n            if (point.branch == Branch::other)",
     "if (true)\n              return true;\n            if (point.branch == Branch::other)"),
    ("gap search without the predicted mode", "source/continuation/gap_filling.cc",
     "return trend.start && predicted_landing(",
     "return false && predicted_landing("),
    ("the gap search solves a start again", "source/continuation/search_memory.cc",
     "if (known != solutions_.end())", "if (false)"),
    ("gap search that keeps landings above Energy max", "source/continuation/gap_filling.cc",
     "if (!(point.measures.energy <= context.params.continuation.energy_max))", "if (false)"),
    ("labels by the energy envelope alone (every point of the mode's family)", "source/continuation/main_branch.cc",
     "if (contact < most - drop || (own[i] && !moves_at_omega(points[i])))", "if (false)"),
    ("main points led by any harmonic", "source/continuation/main_branch.cc",
     "return point.measures.leading_harmonic == 1;", "return true;"),
    ("a field led by another harmonic said to lack contact", "source/app/pipeline.cc",
     "if (p.branch == Branch::other && !moves_at_omega(p))", "if (false)"),
    ("a checkpoint drops the gap search's landings led by a harmonic k > 1", "source/continuation/checkpoint.cc",
     "g.other_harmonic = reader.count(line, g.other_family);", "reader.count(line, g.other_family);"),
    ("the gap search counts no landing led by a harmonic k > 1", "source/continuation/gap_filling.cc",
     "if (!moves_at_omega(point))\n                  ++search.other_harmonic;",
     "if (false)\n                  ++search.other_harmonic;"),
    ("a family's envelope point led by a higher harmonic kept", "source/continuation/main_branch.cc",
     "for (bool removed = true; removed;)", "for (bool removed = false; removed;)"),
    ("an excursion of the own fundamental main whatever leads it", "source/continuation/main_branch.cc",
     "mark(point, moves_at_omega(point) ? Branch::main : Branch::other);", "mark(point, Branch::main);"),
    ("the leading harmonic counts the mean", "source/harmonic_balance/solution_measures.cc",
     "std::max_element(square.begin() + 1, square.end())", "std::max_element(square.begin(), square.end())"),
    ("tongues named whatever their distance from w_j / k", "source/continuation/main_branch.cc",
     "return distance <= continuation_constants::resonance_name_tolerance * r.omega ? r : InternalResonance{0, 0, 0};",
     "return r;"),
    ("leap without the branch with half the harmonics beyond Search reach", "source/continuation/leap.cc",
     "(from_fewer_harmonics(false) || from_fewer_harmonics(true))", "from_fewer_harmonics(false)"),
    ("leap without its last resort", "source/continuation/leap.cc",
     "if (from_guesses(false) || (first_ > 0 && from_guesses(true)) ||", "if (from_guesses(false) ||"),
    ("leap from the segment's first fold even behind its start", "source/continuation/leap.cc",
     ", front_(backbone.points[leap_front(context, backbone, first_, first_fold)])",
     ", front_(backbone.points[first_fold.value_or(backbone.points.size() - 1)])"),
    ("steps without the contact guard", "source/continuation/sequential_steps.cc",
     "<= c.max_contact_change))", "<= 1.0))"),
    ("a point between two of a segment need not continue them", "source/continuation/continuation.cc",
     "stays_on_branch(a, point, params.continuation) && stays_on_branch(b, point, params.continuation);",
     "true;"),
    ("arclength steps may slide along Omega", "source/continuation/arclength_steps.cc",
     "std::abs(to.omega - from.omega) <= c.max_step;", "std::abs(to.omega - from.omega) <= 1e300 * c.max_step;"),
    ("main points' error counts the tongue points", "source/study/study_measures.cc",
     "        if (p.branch == Branch::main)\n", "        if (p.branch == Branch::main || true)\n"),
    ("the range's end on a tongue's flank taken as the branch", "source/continuation/continuation.cc",
     "find_branch_below_at_end(context, backbone, segment);", "(void)segment;"),
    ("fields near a zero of gamma with the force sign flipped", "source/verification/fields.cc",
     "hb.law().displacement(1.0, coefficients_.force[i]);",
     "-hb.law().displacement(1.0, coefficients_.force[i]);"),
    ("the search at the range's end without the main points' guesses", "source/continuation/range_end.cc",
     "if (!above[i] && std::abs(", "if (false && std::abs("),
    ("a range's end climbing a tongue not searched", "source/continuation/range_end.cc",
     "if (!descended && !climbed_with_less_contact(context, backbone, *bottom, reach))", "if (!descended)"),
    ("the two sides of the accumulation point labelled together", "source/continuation/main_branch.cc",
     "if (beyond(points[i].omega, direction, passed) == side_beyond)", "if (!side_beyond)"),
    ("the accumulation point passed at W_acc, inside the climb's truncated top", "source/continuation/main_branch.cc",
     "return params.accumulation_omega * (1 + continuation_constants::accumulation_reach / (m * m));",
     "return params.accumulation_omega;"),
    ("the four-double trailing update skips half of each sixteen rows", "source/base/dense_lu.cc",
     "update_rows<lanes, 16 / lanes>(n, i, l, u0, u1, c0, c1, pair);",
     "update_rows<lanes, 2>(n, i, l, u0, u1, c0, c1, pair);"),
    ("the shooting not started again from the integration's end", "source/verification/forced_floquet.cc",
     "z = settled;", "z.clear();"),
    ("the climb's truncated zone as deep as M / 2's", "source/continuation/accumulation_tongue.cc",
     "(1 - *from / w_acc) / continuation_constants::halved_truncation_reach", "(1 - *from / w_acc)"),
    ("the climb walked down past its converged points", "source/continuation/accumulation_tongue.cc",
     "if (!(estimates[i] > params.continuation.tongue_share))", "if (false)"),
    ("the climb's walk stopped by a point without an estimate", "source/continuation/accumulation_tongue.cc",
     "if (std::isnan(estimates[i]))\n          continue;", "if (std::isnan(estimates[i]))\n          break;"),
    ("the climb's walk from the passing point", "source/continuation/accumulation_tongue.cc",
     "for (const std::size_t i : climb_down(points, low, params.accumulation_omega))",
     "for (const std::size_t i : climb_down(points, low, accumulation_passed(params)))"),
    ("the climb's truncated top not named", "source/app/pipeline.cc",
     "point_stop_signal() == 0 && name_accumulation_tongue(backbone(), estimates_, branch()) > 0", "false"),
    ("the gap search's failed solves not counted", "include/nsm/harmonic_balance/newton_solver.h",
     "d.failed_solves -= earlier.failed_solves;",
     "d.failed_solves = 0;"),
    ("the branch below the range's end may have less contact", "source/continuation/range_end.cc",
     "point.measures.contact_fraction >= last.measures.contact_fraction &&", "true &&"),
    ("contacts shorter than a sample spacing missed", "source/harmonic_balance/active_set.cc",
     "if (!(peak || trough) || std::abs(q[t]) > reach)", "if (true)"),
    ("a lost branch blames no Newton solve on Max iterations", "source/harmonic_balance/newton_solver.cc",
     "status != NOX::StatusTest::Converged && iterations >= impl_->max_iterations}", "false}"),
    ("a study's row whose branch was lost reads as one that reached the range", "source/continuation/leap.cc",
     "        backbone_.end    = above ? BackboneEnd::energy_max : BackboneEnd::lost;\n", ""),
    ("a branch that rises above Energy max called lost", "source/continuation/leap.cc",
     "bool left_energy_range() const { return above_energy_max > 0; }",
     "bool left_energy_range() const { return false; }"),
    ("a row that ended inside the Backbone omegas may lead the energy front", "source/study/study_shared_errors.cc",
     "text_cell(row, column_of(table, \"energy_error_partial\")) != \"yes\";", "true;"),
    ("rows compared on Omegas some of them lack", "source/study/study_shared_errors.cc",
     "if (reference[i] && std::all_of(", "if (reference[i] || std::all_of("),
    ("a swap replaces an output another run swapped in meanwhile", "source/output/output_directory.cc",
     "if (identity(target_) != identity_)", "if (false && identity(target_) != identity_)"),
    ("a default folder taken by another scene file's output", "source/output/output_directory.cc",
     "if (owner == printable(scene))", "if (true)"),
    ("a value the record reads back otherwise accepted", "source/scene/scene_file.cc",
     "        if (value != entry.value)\n          throw InputError(\"parameter '\" + entry.path() + \"' = '\" + printable(entry.value) +",
     "        if (false)\n          throw InputError(\"parameter '\" + entry.path() + \"' = '\" + printable(entry.value) +"),
    ("Cells = 0 searches a band no mesh holds", "source/model/band_cells.cc",
     "if (modes <= most_dofs)", "if (true)"),
    ("the continuum's modes counted from j = 0", "source/model/band_cells.cc",
     "return top * bar.travel_time() / M_PI + 0.5;", "return top * bar.travel_time() / M_PI;"),
    ("the memory estimate blind to the points kept", "source/model/memory_estimate.cc",
     "add(double(scene.continuation.max_steps) * (bytes_per_point + bytes_per_point_unknown * n),",
     "add(0 * double(scene.continuation.max_steps) * (bytes_per_point + bytes_per_point_unknown * n),"),
    ("a row's energy error over part of the Backbone omegas not marked", "source/study/study_measures.cc",
     "return *reached > *low && *reached < *high;", "return *reached > *low && *reached < *low;"),
    ("results that depend on the machine's cores", "source/base/threads.cc",
     "void use_one_thread() { dealii::MultithreadInfo::set_thread_limit(1); }", "void use_one_thread() {}"),
    ("the branch's own fundamental named a tongue", "source/continuation/main_branch.cc",
     "return r.harmonic == 1 && r.mode == mode;", "return false;"),
    ("the unfolding parameter accepted far beyond the Newton tolerance", "source/continuation/branch_context.cc",
     "std::abs(x[1]) > params.harmonic_balance.tolerance", "std::abs(x[1]) > 1e-6"),
    ("a point that comes back over a fold labelled main", "source/continuation/main_branch.cc",
     "on[i] = among[i] && !above[i] && !behind[i];", "on[i] = among[i] && !above[i];"),
    ("one front for all segments", "source/continuation/main_branch.cc",
     "if (i > 0 && points[i].segment != points[i - 1].segment)", "if (false)"),
    ("a leap from fewer harmonics starts from tongue points too", "source/continuation/leap.cc",
     "if (q.branch == Branch::main && context_.beyond(q.omega, front_.omega) &&",
     "if (context_.beyond(q.omega, front_.omega) &&"),
    ("a leap from fewer harmonics puts each harmonic in the next one's slot", "source/continuation/branch_context.cc",
     "std::copy_n(fewer.x.begin(), std::min(fewer.x.size(), guess.size()), guess.begin());",
     "std::copy_n(fewer.x.begin(), std::min(fewer.x.size(), guess.size()) - 1, guess.begin() + 1);"),
    ("a resumed sequential segment starts again from the initial step", "source/continuation/continuation.cc",
     "method.resume_with(c.step);", "method.resume_with(std::nullopt);"),
    ("the automatic range's limit from the mean of the free and held frequencies", "source/model/automatic_range.cc",
     "f.bilinear         = 2 * f.free * f.held / (f.free + f.held);",
     "f.bilinear         = (f.free + f.held) / 2;"),
    ("a compliant wall's automatic range held clamped, not by its spring", "source/model/automatic_range.cc",
     "on_spring = contact.wall == Wall::compliant && contact.sign == ForceSign::physical;",
     "on_spring = false;"),
    ("a resumed verification integrates the points it kept again", "source/verification/time_verification.cc",
     "if (i < known.size() && known[i])", "if (false && i < known.size() && known[i])"),
    ("the previous output removed whole, a user's file in it too", "source/output/output_directory.cc",
     "if (fs::remove(folder, error) || (move_back(folder, target) && remove_empty_folders(folder)))",
     "if (fs::remove_all(folder, error) != static_cast<std::uintmax_t>(-2))"),
    ("a snapshot folder's files checked by type, not by name", "source/output/output_directory.cc",
     "if (inner.is_symlink() || !inner.is_regular_file() ||\n                    !names->count(inner.path().filename().string()))",
     "if (inner.is_symlink() || !inner.is_regular_file())"),
    ("a checkpoint read whatever its checksum", "source/base/checkpoint_reader.cc",
     "intact_                = text.compare(body, std::string::npos, checksum_line(text.substr(0, body))) == 0;",
     "intact_                = true;"),
    ("the error estimate against a quarter of the harmonics", "source/verification/harmonics_estimate.cc",
     "fewer.harmonics              = branch.harmonic_balance.harmonics / 2;",
     "fewer.harmonics              = branch.harmonic_balance.harmonics / 4;"),
    ("the error estimate relative to the energy with fewer harmonics", "source/verification/harmonics_estimate.cc",
     "return std::abs(m.energy / point.measures.energy - 1);",
     "return std::abs(point.measures.energy / m.energy - 1);"),
    ("the estimate's check on a receptance only up to M's band", "source/verification/doubled_harmonics.cc",
     "const Receptance gamma(model, receptance, 2 * band);",
     "const Receptance gamma(model, receptance, band);"),
    ("the estimate's check with its guess shifted by one harmonic", "source/verification/doubled_harmonics.cc",
     "std::copy(x.begin(), x.end(), guess.begin());",
     "std::copy(x.begin() + 1, x.end(), guess.begin());"),
    ("the estimate's check with M + 2 harmonics, not 2 M", "source/verification/doubled_harmonics.cc",
     ": more_(with_harmonics(branch, 2 * branch.harmonic_balance.harmonics))",
     ": more_(with_harmonics(branch, branch.harmonic_balance.harmonics + 2))"),
    ("the estimate's check warns below the factor it names", "source/verification/doubled_harmonics.cc",
     "if (!(check.median_change > under_read_factor * check.median_estimate))",
     "if (!(check.median_change > check.median_estimate))"),
    ("the band check warns on the largest change, not the median", "source/verification/space_estimate.cc",
     "const double energy    = by_energy ? found[found.size() / 2] : 0;",
     "const double energy    = by_energy ? found.back() : 0;"),
    ("the band check's judge not refined", "source/verification/space_estimate.cc",
     "std::make_unique<Discretisation>(model, model.fe().degree + judge_degree_step, 1)",
     "std::make_unique<Discretisation>(model, model.fe().degree + judge_degree_step, 0)"),
    ("the band check counts points that moved to another motion as changes", "source/verification/space_estimate.cc",
     "      if (std::isfinite(c))\n        found.push_back(c);",
     "      found.push_back(std::isfinite(c) ? c : 1e300);"),
    ("the compliant wall's mean stored energy twice too large", "source/harmonic_balance/solution_measures.cc",
     "    return mean / 2;\n  }", "    return mean;\n  }"),
    ("the band check blind to the eigenfrequencies", "source/verification/space_estimate.cc",
     "if (energy <= harmonics_estimate && band.error <= harmonics_estimate)",
     "if (energy <= harmonics_estimate)"),
]


def run(command, cwd, log):
    # A unit test suite (one CTest test) stops at its first failing test.
    with open(log, "w") as out:
        return subprocess.run(command, cwd=cwd, stdout=out, stderr=subprocess.STDOUT,
                              env={**os.environ, "GTEST_FAIL_FAST": "1"}).returncode


def failed_tests(build, log):
    # The physics suite: valgrind's memcheck and the hostile inputs test
    # memory and input safety, which these mutations leave alone, and
    # mutations.texts fails on every planted mutation by design.
    # A mutation is caught by its first failing test: each run stops there,
    # and the unit test suites (seconds each) run before the scene and hard-case
    # runs (up to a minute each), which CTest would otherwise start first.
    failures = []
    for stage, selection in (("unit", ["-E", r"memcheck|hostile|^mutations\.|^scene\.|^hard\."]),
                             ("runs", ["-R", r"^scene\.|^hard\.", "-E", "hostile"])):
        stage_log = log.replace(".log", f".{stage}.log")
        run(["ctest", "-j2", "--timeout", "600", "--stop-on-failure"] + selection, build, stage_log)
        with open(stage_log) as f:
            # A test the build skips (DebugChecks in Release) is listed too:
            # only a failure counts.
            failures = re.findall(r"^\s*\d+ - (\S+) \((?!Skipped|Disabled)", f.read(), re.MULTILINE)
        if failures:
            break
    return failures


def commit_count():
    result = subprocess.run(["git", "rev-list", "--count", "HEAD"], cwd=ROOT, capture_output=True, text=True)
    return int(result.stdout) if result.returncode == 0 else 0


def selected(args):
    chosen = list(enumerate(MUTATIONS))
    if args.only:
        chosen = [(i, m) for i, m in chosen if re.search(args.only, m[0])]
    if args.sample:
        turn = (commit_count() if args.turn is None else args.turn) % args.sample
        chosen = [(i, m) for i, m in chosen if i % args.sample == turn]
        print(f"sample {turn} of {args.sample} (commit {commit_count()}): "
              f"{len(chosen)} of {len(MUTATIONS)} mutations", flush=True)
    return [m for _, m in chosen]


def copy_and_build(work):
    """The tracked sources in work/src, built in work/build; their suite passes."""
    src, build = os.path.join(work, "src"), os.path.join(work, "build")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(build)
    tracked = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                             check=True).stdout.split()
    for path in tracked:
        os.makedirs(os.path.dirname(os.path.join(src, path)) or src, exist_ok=True)
        shutil.copy2(os.path.join(ROOT, path), os.path.join(src, path))
    log = os.path.join(work, "build.log")
    if run(["cmake", src, "-DCMAKE_BUILD_TYPE=Release"], build, log) or run(BUILD, build, log):
        sys.exit(f"the unmutated sources do not build: see {log}")
    baseline = failed_tests(build, os.path.join(work, "baseline.log"))
    if baseline:
        sys.exit(f"the unmutated suite fails: {baseline}")
    print("unmutated: all tests pass", flush=True)
    return src, build


# What the suite runs: the rest (benchmarks) need not be rebuilt.
BUILD = ["cmake", "--build", ".", "-j2", "--target", "nsm-bar", "unit_tests"]


def matches(source, text):
    """The spans of `source` that read as `text` with each run of whitespace
    in it standing for any run (a re-indented or re-wrapped line matches)."""
    words = text.split()
    pattern = r"\s+".join(re.escape(word) for word in words)
    # An identifier at either end must not continue beyond it.
    if re.match(r"\w", words[0]):
        pattern = r"(?<!\w)" + pattern
    if re.search(r"\w$", words[-1]):
        pattern += r"(?!\w)"
    return [m.span() for m in re.finditer(pattern, source)]


def try_mutation(mutation, src, build, work):
    """Applies the mutation, rebuilds, runs the suite, restores the file;
    returns the failing tests, or None if the mutated code does not build
    (a mutation that must be written again, not a bug the suite caught)."""
    name, path, text, replacement = mutation
    file = os.path.join(src, path)
    with open(file) as f:
        original = f.read()
    spans = matches(original, text)
    assert len(spans) == 1, f"{name}: the text occurs {len(spans)} times"
    try:
        with open(file, "w") as f:
            f.write(original[:spans[0][0]] + replacement + original[spans[0][1]:])
        slug = re.sub(r"\W+", "_", name)
        if run(BUILD, build, os.path.join(work, slug + ".build.log")):
            return None
        return failed_tests(build, os.path.join(work, slug + ".log"))
    finally:
        with open(file, "w") as f:
            f.write(original)


def check_texts():
    """Fails unless each mutation's text occurs exactly once in its file."""
    wrong = []
    for name, path, text, _ in MUTATIONS:
        with open(os.path.join(ROOT, path)) as f:
            count = len(matches(f.read(), text))
        if count != 1:
            wrong.append(f"{name}: {path} holds its text {count} times")
    if wrong:
        sys.exit("mutations to match again:\n" + "\n".join(wrong))
    print(f"each of the {len(MUTATIONS)} mutations' texts occurs once")


def main():
    parser = argparse.ArgumentParser(description="Plants bugs and checks that the suite catches each.")
    parser.add_argument("work", nargs="?", default="/tmp/nsm-mutations")
    parser.add_argument("--in-place", action="store_true")
    parser.add_argument("--only")
    parser.add_argument("--sample", type=int)
    parser.add_argument("--turn", type=int, help="with --sample: which N-th (default: the commit count)")
    parser.add_argument("--check-texts", action="store_true")
    args = parser.parse_args()
    if args.check_texts:
        return check_texts()
    mutations = selected(args)
    # A stop restores the mutated file (try_mutation's finally) before exiting.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("stopped"))
    work = os.path.abspath(args.work)
    if args.in_place:
        src, build = ROOT, os.path.join(ROOT, "build")
        os.makedirs(work, exist_ok=True)
    else:
        src, build = copy_and_build(work)
    # Each file is restored by try_mutation: its new time makes the next
    # build of build/ remake what the mutations touched.
    survivors, broken = [], []
    for mutation in mutations:
        start = time.time()
        failures = try_mutation(mutation, src, build, work)
        if failures is None:
            print(f"BROKEN   {mutation[0]}: the mutated code does not build [{time.time() - start:.0f} s]", flush=True)
            broken.append(mutation[0])
            continue
        shown = ", ".join(failures[:6]) + (" ..." if len(failures) > 6 else "")
        print(f"{'caught  ' if failures else 'SURVIVED'} {mutation[0]}: {len(failures)} failing "
              f"({shown}) [{time.time() - start:.0f} s]", flush=True)
        if not failures:
            survivors.append(mutation[0])
    if survivors or broken:
        sys.exit(f"mutations not caught: {survivors}; mutations that do not build: {broken}")
    print(f"every mutation is caught ({len(mutations)})")


if __name__ == "__main__":
    main()
