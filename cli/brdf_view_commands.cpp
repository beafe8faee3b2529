// `gonio brdf eval | info | section | sectslow | map`: looking at a BRDF (thesis GPBRDFSection,
// GPBRDFsectSlow, GPBRDFMap) with the cut given by options instead of hard-coded.
#include <cmath>
#include <cstdio>
#include <memory>

#include "base/math.h"
#include "brdf_cli.h"
#include "brdfsim/analytic_brdf.h"
#include "brdfsim/angular_map.h"
#include "brdfsim/brdf_report.h"
#include "brdfsim/plot.h"
#include "brdfsim/section.h"

namespace gonio::brdfcli {

namespace {

void AddEval(CLI::App& brdf, int* exitCode) {
    auto* cmd = brdf.add_subcommand("eval", "print f(ω'→ω) in 1/sr (angles in degrees)");
    auto path = std::make_shared<std::string>();
    auto angles = std::make_shared<std::vector<double>>();
    auto gridOnly = std::make_shared<bool>(false);
    cmd->add_option("FILE", *path, "grid (.grd)")->required();
    cmd->add_option("ANGLES", *angles, "THETA_IN PHI_IN THETA_OUT PHI_OUT (degrees)")
        ->required()
        ->expected(4);
    cmd->add_flag("--grid", *gridOnly, "sum the splats even when the file has a baked table");
    cmd->callback([=] {
        *exitCode = RunGuarded("eval", [&] {
            const LoadedBrdf loaded = LoadGrid(*path, !*gridOnly);
            const auto& a = *angles;
            std::vector<float> f(loaded.brdf->NumComponents());
            loaded.brdf->EvalAngles(a[0] * kDegree, a[1] * kDegree, a[2] * kDegree, a[3] * kDegree,
                                    f.data());
            for (std::size_t c = 0; c < f.size(); ++c) {
                std::printf("%s%.6g", c ? " " : "", f[c]);
            }
            std::printf("\n");
        });
    });
}

void AddInfo(CLI::App& brdf, int* exitCode) {
    auto* cmd = brdf.add_subcommand("info", "statistics of a photon map or a grid");
    auto path = std::make_shared<std::string>();
    cmd->add_option("FILE", *path, "photon map (.pm) or grid (.grd)")->required();
    cmd->callback([=] {
        *exitCode = RunGuarded("info", [&] {
            if (IsGrdFile(*path)) {
                const GrdFile file = ReadGrd(*path);
                PrintGrdInfo(*path, file, stdout);
            } else {
                PrintPhotonMapInfo(*path, SummarizePhotonMap(*path), stdout);
            }
        });
    });
}

// The cut options shared by section and sectslow; list options give several cuts.
struct CutArgs {
    std::vector<double> thetaIn{45}, phiIn{0}, thetaOut{45}, phiOut{0};
    std::string vary = "theta-out";
    double from = NAN, to = NAN;
    bool relative = false, reciprocal = false;
    std::string plot, title = "BRDF cross section";
    std::vector<int> plotSize{800, 450};
    double yMax = NAN;
    std::vector<std::string> analytic, labels;
    int component = 0;
};

void AddCutOptions(CLI::App* cmd, CutArgs* args) {
    cmd->add_option("--theta-in", args->thetaIn, "fixed θ_in, degrees (several: several cuts)")
        ->delimiter(',');
    cmd->add_option("--phi-in", args->phiIn, "fixed φ_in, degrees")->delimiter(',');
    cmd->add_option("--theta-out", args->thetaOut, "fixed θ_out, degrees")->delimiter(',');
    cmd->add_option("--phi-out", args->phiOut, "fixed φ_out, degrees")->delimiter(',');
    cmd->add_option("--vary", args->vary, "theta-in, phi-in, theta-out or phi-out")
        ->capture_default_str();
    cmd->add_option("--from", args->from, "start of the varying angle, degrees");
    cmd->add_option("--to", args->to, "end of the varying angle, degrees");
    cmd->add_flag("--relative", args->relative,
                  "φ_out counts from φ_in (x is φ_out − φ_in when φ_out varies)");
    cmd->add_flag("--reciprocal", args->reciprocal,
                  "where θ_out > θ_in evaluate f(ω'→ω) as f(ω→ω') (Helmholtz reciprocity), "
                  "so that photons leave by the less grazing direction");
    cmd->add_option("--plot", args->plot,
                    "write a labelled plot: .svg, or an image (.png, .tif, .jpg, ...)");
    cmd->add_option("--title", args->title, "the plot's title")->capture_default_str();
    cmd->add_option("--plot-size", args->plotSize, "the plot's WIDTH HEIGHT in pixels")
        ->expected(2)
        ->capture_default_str();
    cmd->add_option("--y-max", args->yMax, "top of the plot's f axis (default: from the data)");
    cmd->add_option("--label", args->labels,
                    "legend text of the curves in order (grids × cuts, then analytic; repeatable)")
        ->expected(1)
        ->take_all();
    cmd->add_option("--analytic", args->analytic,
                    "overlay lambert:ALBEDO or phong:KD,KS,EXPONENT (repeatable)");
    cmd->add_option("--component", args->component, "colour component to plot")
        ->capture_default_str();
}

std::vector<SectionCut> MakeCuts(const CutArgs& args, int samples) {
    SectionCut base;
    base.vary = ParseSectionAxis(args.vary);
    base.relativePhi = args.relative;
    base.reciprocal = args.reciprocal;
    base.samples = samples;
    DefaultRange(base.vary, &base.from, &base.to);
    if (!std::isnan(args.from)) base.from = args.from;
    if (!std::isnan(args.to)) base.to = args.to;
    if (samples < 1) throw UsageError("NR_SAMPLES must be at least 1");
    std::vector<SectionCut> cuts;
    for (double ti : args.thetaIn) {
        for (double pi : args.phiIn) {
            for (double to : args.thetaOut) {
                for (double po : args.phiOut) {
                    SectionCut cut = base;
                    cut.thetaIn = ti, cut.phiIn = pi, cut.thetaOut = to, cut.phiOut = po;
                    cuts.push_back(cut);
                }
            }
        }
    }
    return cuts;
}

// The plot's size and axis; checked before any section is computed.
PlotOptions MakePlotOptions(const CutArgs& args) {
    PlotOptions options;
    options.width = args.plotSize[0];
    options.height = args.plotSize[1];
    if (!std::isnan(args.yMax)) options.yMax = args.yMax;
    try {
        const PlotLayout check(options, {});
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--plot: ") + e.what());
    }
    return options;
}

// Prints the table (x, then every component of every series) and writes the plot.
void RunSections(const std::vector<std::pair<std::string, const Brdf*>>& sources,
                 const CutArgs& args, int samples) {
    const std::vector<SectionCut> cuts = MakeCuts(args, samples);
    if (!args.plot.empty()) MakePlotOptions(args);
    std::vector<PlotSeries> series;
    std::vector<std::vector<std::vector<float>>> columns;
    std::string header = "# " + std::string(SectionAxisName(cuts[0].vary)) + "_deg";
    for (const auto& [name, brdf] : sources) {
        if (args.component < 0 || args.component >= brdf->NumComponents()) {
            throw UsageError("--component must be below " + std::to_string(brdf->NumComponents()));
        }
        for (const SectionCut& cut : cuts) {
            const Section section = ComputeSection(*brdf, cut);
            PlotSeries s;
            s.label = name + " " + cut.Label();
            s.x = section.x;
            for (const auto& f : section.f) s.y.push_back(f[args.component]);
            series.push_back(s);
            columns.push_back(section.f);
            for (int c = 0; c < brdf->NumComponents(); ++c) {
                header += "  [" + s.label + "]" +
                          (brdf->NumComponents() > 1 ? ":" + std::to_string(c) : "");
            }
        }
    }
    for (const std::string& spelling : args.analytic) {
        const AnalyticBrdf analytic = AnalyticBrdf::Parse(spelling);
        for (const SectionCut& cut : cuts) {
            PlotSeries s;
            s.label = spelling + " " + cut.Label();
            s.dashed = true;
            std::vector<std::vector<float>> column;
            for (int i = 0; i < cut.samples; ++i) {
                const double x = cut.samples == 1
                                     ? cut.from
                                     : cut.from + (cut.to - cut.from) * i / (cut.samples - 1);
                double ti, pi, to, po;
                CutAngles(cut, x, &ti, &pi, &to, &po);
                const Imath::V3f a = DirectionFromAngles(ti, pi), b = DirectionFromAngles(to, po);
                const double f =
                    analytic.Eval(Imath::V3d(a.x, a.y, a.z), Imath::V3d(b.x, b.y, b.z));
                s.x.push_back(x);
                s.y.push_back(f);
                column.push_back({static_cast<float>(f)});
            }
            series.push_back(s);
            columns.push_back(column);
            header += "  [" + s.label + "]";
        }
    }
    if (args.labels.size() > series.size()) {
        throw UsageError(std::to_string(args.labels.size()) + " --label for " +
                         std::to_string(series.size()) + " curves");
    }
    for (std::size_t i = 0; i < args.labels.size(); ++i) series[i].label = args.labels[i];
    std::printf("%s\n", header.c_str());
    for (int i = 0; i < samples; ++i) {
        std::printf("%9.3f", series[0].x[i]);
        for (const auto& column : columns) {
            for (float v : column[i]) std::printf(" %12.6g", v);
        }
        std::printf("\n");
    }
    if (!args.plot.empty()) {
        PlotLabels labels;
        labels.title = args.title;
        labels.xLabel = cuts[0].AxisLabel() + " (degrees)";
        labels.yLabel = "f (1/sr)";
        WritePlot(args.plot, labels, series, MakePlotOptions(args));
        std::fprintf(stderr, "wrote %s\n", args.plot.c_str());
    }
}

std::string BaseName(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

void AddSection(CLI::App& brdf, int* exitCode) {
    auto* cmd = brdf.add_subcommand("section", "cross sections of grids (GPBRDFSection)");
    auto samples = std::make_shared<int>(0);
    auto files = std::make_shared<std::vector<std::string>>();
    auto args = std::make_shared<CutArgs>();
    auto baked = std::make_shared<bool>(false);
    cmd->add_option("NR_SAMPLES", *samples, "points along the cut")->required();
    cmd->add_option("GRIDS", *files, "one or more grids (.grd)")->required()->expected(1, -1);
    AddCutOptions(cmd, args.get());
    cmd->add_flag("--baked", *baked, "use the baked table where the file has one");
    cmd->callback([=] {
        *exitCode = RunGuarded("section", [&] {
            std::vector<LoadedBrdf> loaded;
            std::vector<std::pair<std::string, const Brdf*>> sources;
            for (const std::string& path : *files) {
                loaded.push_back(LoadGrid(path, *baked));
                sources.emplace_back(BaseName(path), loaded.back().brdf);
            }
            RunSections(sources, *args, *samples);
        });
    });
}

void AddSectSlow(CLI::App& brdf, int* exitCode) {
    auto* cmd = brdf.add_subcommand(
        "sectslow", "cross sections straight from a photon map, every splat summed");
    auto spread = std::make_shared<std::string>();
    auto energyMin = std::make_shared<double>(0.0);
    auto samples = std::make_shared<int>(0);
    auto input = std::make_shared<std::string>();
    auto args = std::make_shared<CutArgs>();
    auto norm = std::make_shared<std::string>("l2");
    auto horizon = std::make_shared<std::string>("reflect");
    auto knn = std::make_shared<int>(0);
    cmd->add_option("SPREAD", *spread, "splat radius: radians, or degrees as 17deg")->required();
    cmd->add_option("ENERGY_MIN", *energyMin, "photons with less energy are skipped")->required();
    cmd->add_option("NR_SAMPLES", *samples, "points along the cut")->required();
    cmd->add_option("INPUT", *input, "photon map (.pm)")->required();
    AddCutOptions(cmd, args.get());
    AddNormOption(cmd, norm.get(), horizon.get());
    AddKnnOption(cmd, knn.get());
    cmd->callback([=] {
        *exitCode = RunGuarded("sectslow", [&] {
            PhotonMapSettings settings =
                MakeSettings(ParseSpread(*spread), *energyMin, *norm, *horizon);
            settings.simple = true;
            settings.knn = *knn;
            const LoadedBrdf loaded = LoadBrdf(*input, settings, false);
            RunSections({{BaseName(*input), loaded.brdf}}, *args, *samples);
        });
    });
}

void AddMap(CLI::App& brdf, int* exitCode) {
    auto* cmd = brdf.add_subcommand("map", "angular plot of the outgoing hemisphere (GPBRDFMap)");
    auto options = std::make_shared<AngularMapOptions>();
    auto spread = std::make_shared<std::string>();
    auto input = std::make_shared<std::string>();
    auto output = std::make_shared<std::string>();
    auto colourMap = std::make_shared<std::string>("none");
    auto norm = std::make_shared<std::string>("l2");
    auto horizon = std::make_shared<std::string>("reflect");
    auto knn = std::make_shared<int>(0);
    cmd->add_option("SIZE", options->size, "image width and height in pixels")->required();
    cmd->add_option("ENERGY_SCALE", options->energyScale, "pixel value = f × ENERGY_SCALE")
        ->required();
    cmd->add_option("SPREAD", *spread, "splat radius for a .pm input (a .grd keeps its own)")
        ->required();
    cmd->add_option("THETA_LIGHT", options->thetaLight, "degrees")->required();
    cmd->add_option("PHI_LIGHT", options->phiLight, "degrees")->required();
    cmd->add_option("INPUT", *input, "grid (.grd) or photon map (.pm)")->required();
    cmd->add_option("OUTPUT", *output, "image (.tif, .png, .exr)")->required();
    cmd->add_option("--colormap", *colourMap, "none (components as RGB), grey, viridis, heat")
        ->capture_default_str();
    cmd->add_flag("--scale-bar", options->scaleBar, "a colour strip from 0 to 1/ENERGY_SCALE");
    AddNormOption(cmd, norm.get(), horizon.get());
    AddKnnOption(cmd, knn.get());
    cmd->callback([=] {
        *exitCode = RunGuarded("map", [&] {
            options->colourMap = ParseColourMap(*colourMap);
            PhotonMapSettings settings = MakeSettings(ParseSpread(*spread), 0.0, *norm, *horizon);
            settings.knn = *knn;
            const LoadedBrdf loaded = LoadBrdf(*input, settings, true);
            if (loaded.grd &&
                std::abs(loaded.grd->splats->Params().radius - ParseSpread(*spread)) > 1e-6) {
                std::fprintf(stderr, "note: %s was optimised with spread %.4f; SPREAD ignored\n",
                             input->c_str(), loaded.grd->splats->Params().radius);
            }
            const AngularMapResult result = WriteAngularMap(*loaded.brdf, *options, *output);
            std::printf("%s: %dx%d, max f %.6g 1/sr%s\n", output->c_str(), options->size,
                        options->size, result.maxValue,
                        options->scaleBar ? (", scale bar 0.." +
                                             std::to_string(1.0 / options->energyScale) + " 1/sr")
                                                .c_str()
                                          : "");
        });
    });
}

}  // namespace

void AddViewCommands(CLI::App& brdf, int* exitCode) {
    AddEval(brdf, exitCode);
    AddInfo(brdf, exitCode);
    AddSection(brdf, exitCode);
    AddSectSlow(brdf, exitCode);
    AddMap(brdf, exitCode);
}

}  // namespace gonio::brdfcli
