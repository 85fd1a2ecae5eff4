// adapter-report: how an engine adapter behaves against the analytic references, over a sweep of
// stiffness, mass ratio, time step and solver iterations (docs/<engine>-report.md). Run through
// scripts/adapter-report.sh.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "coupled_report.hpp"
#include "report_scenes.hpp"
#include "scene_engine.hpp"
#include "tool_main.hpp"

namespace {

using namespace plascap;
using Clock = std::chrono::steady_clock;

struct OscillatorRun {
    bool finite = true;  // no NaN or infinity anywhere
    bool stable = true;  // finite, no runaway stretch, the anchor held within 0.1 m
    Regime regime = Regime::RigidPlastic;
    double joint_omega_dt = 0.0;  // from the row's effective mass (what eq. 3.2 sees)
    double peak = 0.0, residual = 0.0, anchor_drift = 0.0, microseconds_per_step = 0.0;
};

OscillatorRun run_oscillator(const std::string& engine_name, const report::OscillatorCase& c, bool rigid = false) {
    Scene scene = report::oscillator_scene(c);
    if (rigid) scene.joints[1].settings.modes[index(Dof::N)] = DofMode::Rigid;  // Bullet's own locked row
    const std::unique_ptr<SceneEngine> engine = make_engine(engine_name, scene);
    OscillatorRun r;
    const double gap0 = scene.bodies[0].position[1] - scene.bodies[1].position[1];
    const double limit = 10 * std::max({c.peak(), c.capacity() / c.stiffness, 0.01});
    const Clock::time_point start = Clock::now();
    for (std::size_t i = 0; i < scene.steps(); ++i) {
        engine->step();
        const BodyState anchor = engine->body(0), load = engine->body(1);
        const double stretch = (anchor.position[1] - load.position[1]) - gap0;
        const double drift = std::hypot(anchor.position[0], anchor.position[1] - scene.bodies[0].position[1], anchor.position[2]);
        if (!std::isfinite(stretch) || !std::isfinite(drift)) r.finite = false;
        if (!r.finite || std::abs(stretch) > limit || !(drift < 0.1)) r.stable = false;
        r.peak = std::max(r.peak, stretch);
        r.anchor_drift = std::max(r.anchor_drift, std::isfinite(drift) ? drift : INFINITY);
    }
    r.microseconds_per_step = std::chrono::duration<double, std::micro>(Clock::now() - start).count() / scene.steps();
    if (rigid) return r;
    const ElasticPlasticLaw& law = *engine->joint_law(1)->law(Dof::N);
    r.regime = law.regime();
    r.joint_omega_dt = law.omega_dt();
    r.residual = law.plastic_offset();
    return r;
}

std::string percent(double value, double reference) {
    std::ostringstream s;
    s << std::showpos << std::fixed << std::setprecision(2) << 100 * (value - reference) / reference << " %";
    return s.str();
}

void accuracy_table(std::ostream& md, const std::string& engine) {
    md << "## The suddenly loaded oscillator against ω·dt\n\n"
          "A 1 kg load on a spring k = 100 N/m with capacity F = W/0.75 under g = 10 m/s², hanging from a\n"
          "1 kg anchor that the world holds rigidly (values.md: peak d = F²/(2k(F − W)) = 0.2667 m, residual\n"
          "plastic displacement d − F/k = 0.1333 m). The issue asks for the residual within 2 % at ω·dt ≤ 0.1.\n"
          "Eq. 3.2 sees the row's effective mass (½ kg here), so it switches to rigid-plastic at ω·dt = 0.18.\n\n"
          "| ω·dt | dt [s] | regime | peak | error | residual | error |\n|---|---|---|---|---|---|---|\n";
    for (double omega_dt : {0.003, 0.01, 0.03, 0.1, 0.15, 0.2, 0.5}) {
        report::OscillatorCase c;
        c.dt = omega_dt / c.omega();
        c.iterations = 20;
        const OscillatorRun r = run_oscillator(engine, c);
        md << "| " << omega_dt << " | " << c.dt << " | " << regime_name(r.regime) << " | " << std::setprecision(4)
           << r.peak << " | " << percent(r.peak, c.peak()) << " | " << r.residual << " | "
           << percent(r.residual, c.residual()) << " |\n";
    }
    md << '\n';
}

void stability_map(std::ostream& md, std::ostream& csv, const std::string& engine) {
    csv << "iterations,stiffness,mass_ratio,dt,omega_dt,joint_omega_dt,regime,stable,peak,residual,exact_residual,"
           "residual_error,anchor_drift,us_per_step\n";
    md << "## Stability map\n\n"
          "The same oscillator over stiffness k, mass ratio (load/anchor: a heavy load on a light anchor is\n"
          "the hard case for an iterative solver), time step and solver iterations. A cell shows the regime\n"
          "(EP elastic-plastic, RP the stiff fallback to rigid-plastic). EP: the residual plastic\n"
          "displacement's error against the exact elastic–plastic value. RP holds the load without flowing\n"
          "(W < F; the limit of k → ∞), so the cell gives instead how far the joint sagged, beside the sag\n"
          "of Bullet's own locked row in its place (\"rigid\"): an iterative solver carrying a heavy load on\n"
          "a light body does not converge in a few iterations, and both sag alike.\n"
          "UNSTABLE: a NaN or infinity. GAVE WAY: finite, but the load ran away (over ten times the\n"
          "analytic peak).\n"
          "Every row is in the CSV beside this file.\n\n";
    const double stiffnesses[] = {10, 1e3, 1e5, 1e7, 1e12};
    const double ratios[] = {1, 10, 100, 1e3, 1e4};
    const double steps[] = {1.0 / 30, 1.0 / 60, 1.0 / 240, 1.0 / 1000};
    int unstable = 0, gave_way = 0, cases = 0;
    double worst_ep = 0.0, cost_sum = 0.0;
    for (int iterations : {4, 10, 50}) {
        md << "### " << iterations << " solver iterations\n\n| k [N/m] | dt [s] |";
        for (double r : ratios) md << " ratio " << r << " |";
        md << "\n|---|---|---|---|---|---|---|\n";
        for (double k : stiffnesses) {
            for (double dt : steps) {
                md << "| " << k << " | 1/" << std::lround(1 / dt) << " |";
                for (double ratio : ratios) {
                    report::OscillatorCase c;
                    c.stiffness = k;
                    c.mass_ratio = ratio;
                    c.dt = dt;
                    c.iterations = iterations;
                    c.periods = 3.0;
                    const OscillatorRun r = run_oscillator(engine, c);
                    ++cases;
                    cost_sum += r.microseconds_per_step;
                    const double error = (r.residual - c.residual()) / c.residual();
                    csv << iterations << ',' << k << ',' << ratio << ',' << dt << ',' << c.omega() * dt << ','
                        << r.joint_omega_dt << ',' << regime_name(r.regime) << ',' << r.stable << ',' << r.peak << ','
                        << r.residual << ',' << c.residual() << ',' << error << ',' << r.anchor_drift << ','
                        << r.microseconds_per_step << '\n';
                    std::ostringstream cell;
                    if (!r.finite) {
                        cell << "UNSTABLE";
                        ++unstable;
                    } else if (!r.stable) {
                        const OscillatorRun locked = run_oscillator(engine, c, true);
                        cell << "GAVE WAY (rigid sag " << std::setprecision(1) << locked.peak << " m)";
                        ++gave_way;
                    } else if (r.regime == Regime::ElasticPlastic) {
                        cell << "EP " << std::showpos << std::fixed << std::setprecision(1) << 100 * error << " %";
                        if (c.omega() * dt <= 0.1) worst_ep = std::max(worst_ep, std::abs(error));
                    } else {
                        const OscillatorRun locked = run_oscillator(engine, c, true);
                        cell << "RP sag " << std::setprecision(1) << r.peak << " m (rigid " << locked.peak << ")";
                    }
                    md << ' ' << cell.str() << " |";
                }
                md << '\n';
            }
        }
        md << '\n';
        std::cerr << "adapter-report: stability map, " << iterations << " iterations done\n";
    }
    md << "**Summary**: " << cases << " cases, " << unstable << " unstable (NaN or infinity), " << gave_way
       << " gave way; the worst residual error in the\n"
       << "elastic-plastic regime with ω·dt ≤ 0.1 is " << std::setprecision(3) << 100 * worst_ep
       << " %; a step costs " << std::setprecision(3) << cost_sum / cases << " µs on average (two bodies, two joints).\n\n";
}

// The paper's tension block (§3): our first steps beside Table 3.5 and Table 3.6.
void paper_tables(std::ostream& md, const std::string& engine, const std::string& scenes) {
    Scene scene = read_scene_file(scenes + "/paper-tension-block.json");
    struct Row { const char* time; const char* location; const char* velocity; const char* impulse; const char* strain; };
    const Row paper[] = {{"0.017", "-0.0028", "-0.17", "0", "0"}, {"0.033", "-0.0046", "-0.11", "1330", "0.001"},
                         {"0.050", "-0.0056", "-0.056", "1330", "0.003"}, {"0.067", "-0.0056", "-0.001", "1330", "0.004"},
                         {"0.083", "-0.0056", "0.0", "1000", "0.004"}};
    auto run_table = [&](const Scene& s, const char* title, const char* note, bool with_paper) {
        const std::unique_ptr<SceneEngine> e = make_engine(engine, s);
        md << "### " << title << "\n\n" << note << "\n\n| time [s] | location [m] | velocity [m/s] | impulse [N·s] | plastic [m] |"
           << (with_paper ? " paper: location | velocity | impulse | plastic strain |\n|---|---|---|---|---|---|---|---|---|\n"
                          : "\n|---|---|---|---|---|\n");
        for (int i = 0; i < 5; ++i) {
            e->step();
            const BodyState b = e->body(0);
            const PlasticJointLaw* law = e->joint_law(0);
            const double impulse = law ? std::abs(e->joint_forces(0)[index(Dof::N)]) * s.dt : 0.0;
            md << "| " << std::fixed << std::setprecision(3) << e->time() << " | " << std::setprecision(4)
               << b.position[1] + 1.5 << " | " << std::setprecision(3) << b.velocity[1] << " | " << std::setprecision(0)
               << impulse << " | " << std::setprecision(4) << (law ? law->plastic_displacement() : 0.0) << " |";
            if (with_paper) {
                md << ' ' << paper[i].location << " | " << paper[i].velocity << " | " << paper[i].impulse << " | "
                   << paper[i].strain << " |";
            }
            md << '\n' << std::defaultfloat;
        }
        md << '\n';
    };
    md << "## The paper's tension block\n\n";
    run_table(scene, "Table 3.5: rigid-plastic, the joint taking hold in the second step",
              "6000 kg, capacity 80 kN (impulse bound 1333 N·s per step; the paper rounds to 1330), g = 10, dt = 1/60, "
              "10 iterations, `examples/scenes/paper-tension-block.json`. The paper's plastic strain is its own "
              "measure; our column is the accumulated plastic elongation.",
              true);
    scene.joints[0].engage_at = 0.0;
    scene.joints[0].settings.laws[index(Dof::N)].stiffness = 200e9 * 4e-4 / 3.0;
    run_table(scene, "Table 3.6: stiffness-limited (EA/L of the steel, ω·dt = 1.1 > 0.25), from the first step",
              "Eq. 3.2 switches the joint to rigid-plastic; as in the paper's Table 3.6 the block does not move "
              "and the joint carries the weight, 1000 N·s per step.",
              false);
}

void charpy_against_dt(std::ostream& md, const std::string& engine, const std::string& scenes) {
    md << "## Charpy impact against the time step\n\n"
          "`examples/scenes/charpy-impact.json`; the author expected ≈ 122 J (64 N·m × 1.9 rad) and measured\n"
          "90–170 J for steps of 0.05–0.2 ms.\n\n| dt [ms] | absorbed [J] | plastic rotation [rad] | wall time [s] |\n|---|---|---|---|\n";
    for (double dt : {2e-4, 1e-4, 5e-5}) {
        Scene scene = read_scene_file(scenes + "/charpy-impact.json");
        scene.dt = dt;
        const std::unique_ptr<SceneEngine> e = make_engine(engine, scene);
        const Clock::time_point start = Clock::now();
        for (std::size_t i = 0; i < scene.steps(); ++i) e->step();
        const double wall = std::chrono::duration<double>(Clock::now() - start).count();
        const PlasticJointLaw& notch = *e->joint_law(0);
        md << "| " << dt * 1e3 << " | " << std::fixed << std::setprecision(1) << notch.dissipated() << " | "
           << std::setprecision(2) << notch.plastic_rotation() << " | " << std::setprecision(3) << wall << " |\n"
           << std::defaultfloat;
    }
    md << '\n';
}

// The analytic value of an example joint where one exists.
std::string analytic(const std::string& scene, const std::string& joint) {
    if (scene == "paper-tension-block.json" && joint == "top") {
        return "0.0027778 m (3 steps at 80 kN against 60 kN after 1 free step), 222.2 J";
    }
    if (scene == "charpy-impact.json" && joint == "notch") return "≈ 122 J expected (author: 90–170 J measured)";
    return "—";
}

void cross_engine(std::ostream& md, const std::string& scenes) {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
        if (entry.path().extension() == ".json") files.push_back(entry.path().filename().string());
    }
    std::sort(files.begin(), files.end());
    const std::vector<std::string> engines = available_engines();
    md << "# Every example scene on every engine\n\n"
          "Generated by `scripts/adapter-report.sh` (`adapter-report --cross-engine`). Per joint: accumulated\n"
          "plastic displacement [m] / rotation [rad], dissipated energy [J], and when it broke. Engines:\n"
          "`bullet` (plascap::BulletPlasticConstraint), `bullet-spring2` (btGeneric6DofSpring2Constraint),\n"
          "`bullet-6dof-spring` (btGeneric6DofSpringConstraint),\n"
          "`ode` (dWorldQuickStep), `ode-step` (dWorldStep, the Dantzig LCP). A ⚠ marks a run in which the\n"
          "engine reported a problem it carried on from (plastic-sim prints it).\n\n";
    for (const std::string& file : files) {
        const Scene scene = read_scene_file(scenes + "/" + file);
        md << "## " << file << "\n\n| joint | engine | plastic [m] | plastic [rad] | dissipated [J] | broken at [s] | analytic |\n"
              "|---|---|---|---|---|---|---|\n";
        for (const std::string& engine_name : engines) {
            std::unique_ptr<SceneEngine> engine = make_engine(engine_name, scene);
            std::string failure;
            try {
                for (std::size_t i = 0; i < scene.steps(); ++i) engine->step();
            } catch (const std::exception& e) {
                failure = e.what();
            }
            const std::string mark = engine->warnings().empty() ? "" : " ⚠";
            for (std::size_t j = 0; j < scene.joints.size(); ++j) {
                const PlasticJointLaw* law = engine->joint_law(j);
                md << "| " << scene.joints[j].name << " | " << engine_name << mark << " | ";
                if (!failure.empty()) {
                    md << "failed: " << failure << " | | | | |\n";
                    continue;
                }
                md << std::setprecision(5) << (law ? law->plastic_displacement() : 0.0) << " | "
                   << (law ? law->plastic_rotation() : 0.0) << " | " << std::setprecision(4) << (law ? law->dissipated() : 0.0)
                   << " | " << (law && law->broken() ? std::to_string(*law->broken_at()).substr(0, 6) : std::string("—"))
                   << " | " << analytic(file, scene.joints[j].name) << " |\n";
            }
            std::cerr << "adapter-report: " << file << " on " << engine_name << " done\n";
        }
        md << '\n';
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"adapter-report: an engine adapter against the analytic references"};
    std::string engine = "bullet", scenes, markdown, csv, cross, coupled, plot_data;
    app.add_option("--engine", engine, "Engine to report on")->capture_default_str();
    app.add_option("--scenes", scenes, "The example scene directory (examples/scenes); not with --coupled");
    app.add_option("--markdown", markdown, "Write the engine's report here (with --csv)");
    app.add_option("--csv", csv, "Write every stability-map case here (with --markdown)");
    app.add_option("--cross-engine", cross, "Instead: run every example scene on every engine; write the table here");
    app.add_option("--coupled", coupled, "Instead: the coupled yield scheme's onset and flow on every engine; write "
                                         "the report here (docs/coupled-yield-report.md)");
    app.add_option("--plot-data", plot_data, "With --coupled: the flow table as whitespace-separated columns, for gnuplot");
    return tool_main("adapter-report", app, argc, argv, [&] {
        if (!coupled.empty()) {
            std::ofstream out(coupled);
            if (!out) throw InputError("cannot write " + coupled);
            std::ofstream plot;
            if (!plot_data.empty()) {
                plot.open(plot_data);
                if (!plot) throw InputError("cannot write " + plot_data);
            }
            report::coupled_report(out, plot_data.empty() ? nullptr : &plot);
            return 0;
        }
        if (!plot_data.empty()) throw InputError("--plot-data goes with --coupled");
        if (scenes.empty()) throw InputError("give --scenes DIR (the example scenes), or --coupled FILE");
        if (!cross.empty()) {
            std::ofstream out(cross);
            if (!out) throw InputError("cannot write " + cross);
            cross_engine(out, scenes);
            return 0;
        }
        if (markdown.empty() || csv.empty()) throw InputError("give --markdown and --csv, or --cross-engine");
        std::ofstream md(markdown), table(csv);
        if (!md || !table) throw InputError("cannot write " + markdown + " or " + csv);
        md << "# The " << engine << " adapter against the analytic references\n\n"
           << "Generated by `scripts/adapter-report.sh " << engine << "` (" << make_engine(engine, report::oscillator_scene({}))->description()
           << "). Timings are of the machine that ran it.\n\n";
        paper_tables(md, engine, scenes);
        accuracy_table(md, engine);
        stability_map(md, table, engine);
        charpy_against_dt(md, engine, scenes);
        return 0;
    });
}
