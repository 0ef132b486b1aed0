#include "RenderItems.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "ImageDifference.h"
#include "prescription/NumberText.h"
#include "Render.h"
#include "SiteFiles.h"

namespace lenslab {

namespace fs = std::filesystem;

RenderPlan renderPlan(const ReportOptions& o) {
    RenderPlan p;
    p.spp = o.quick ? 4 : o.spp;
    p.width = o.quick ? 96 : o.width;
    p.ghostModel = o.quick ? "paraxial" : "exact";
    for (int s = 1; s * 4 <= p.spp; s *= 2) p.speedSpps.push_back(s);
    return p;
}

namespace {

constexpr double kDifferenceGain = 4;

int heightFor(const SceneSource& scene, int width) {
    if (scene.xResolution > 0 && scene.yResolution > 0)
        return std::max(1, static_cast<int>(std::lround(double(width) * scene.yResolution / scene.xResolution)));
    return std::max(1, width * 2 / 3);
}

nlohmann::json renderRecordJson(const RenderRecord& r) {
    return {{"image", r.image}, {"mode", r.mode}, {"width", r.width}, {"height", r.height}, {"spp", r.spp},
            {"fstop", r.fstop}, {"exposure", r.exposure}, {"setup_seconds", r.setupSeconds}, {"render_seconds", r.renderSeconds},
            {"camera_rays", r.cameraRays}, {"blocked_camera_rays", r.blockedCameraRays}, {"rays_traced", r.raysTraced}};
}

RenderRecord renderRecordFromJson(const nlohmann::json& j) {
    RenderRecord r;
    r.image = j.at("image").get<std::string>();
    r.mode = j.at("mode").get<std::string>();
    r.width = j.at("width").get<int>();
    r.height = j.at("height").get<int>();
    r.spp = j.at("spp").get<int>();
    r.fstop = j.at("fstop").get<double>();
    r.exposure = j.at("exposure").get<double>();
    r.setupSeconds = j.at("setup_seconds").get<double>();
    r.renderSeconds = j.at("render_seconds").get<double>();
    r.cameraRays = j.at("camera_rays").get<std::uint64_t>();
    r.blockedCameraRays = j.at("blocked_camera_rays").get<std::uint64_t>();
    r.raysTraced = j.at("rays_traced").get<std::uint64_t>();
    return r;
}

struct RenderJob {
    const SceneSource& scene;
    const LensEntry& lens;
    std::string mode;
    int spp, width, height;
    double fstop;
    std::string ghostModel;                       // for the scenes whose camera asks for ghosts
    std::optional<bool> spectral = std::nullopt;  // unset: as the lens decides
    // A sensor's readout (the sensor ladder) of the crop window; its text names the item.
    std::optional<std::string> sensor = std::nullopt;
    std::optional<std::array<double, 4>> crop = std::nullopt;
    std::string variant = "";  // told apart in the item's id and image name ("-iso1600")

    // The radiometric camera weight averages the exit pupil's solid angle, about pi / (4 N^2) of the
    // scene radiance: scaling by its inverse shows every lens and f-number at the scene's brightness.
    // A sensor's output is developed already.
    double exposure() const { return sensor ? 1.0 : 4 * fstop * fstop / M_PI; }

    RenderSettings settings(int threads) const {
        RenderSettings s;
        s.scenePath = scene.path;
        s.camera.lensFile = lens.facts.path;
        s.camera.fstop = Setting{fstop, "report --render-fstop"};
        s.camera.mode = mode;
        s.camera.spectral = spectral;
        s.camera.ghostModel = ghostModel;
        s.spp = spp;
        s.width = width;
        s.height = height;
        s.threads = threads;
        if (sensor) s.sensor = sensorSpecFromPairs(parseSensorPairs(*sensor));
        s.crop = crop;
        return s;
    }

    std::string hash() const {
        InputsHash h = itemInputs("render");
        for (const std::string& f : scene.files) h.addFile(f);
        h.addFile(lens.facts.path).add(mode).add(double(spp)).add(double(width)).add(double(height)).add(fstop).add(exposure());
        if (spectral) h.add(*spectral ? "spectral" : "rgb");
        if (ghostModel != "exact") h.add(ghostModel);  // the exact model's renders keep their earlier hash
        if (sensor) h.add("sensor " + *sensor);
        if (crop)
            for (double c : *crop) h.add(c);
        return h.hex();
    }
};

// Runs a render through the cache, counting actual renders; nullopt when it failed.
std::optional<RenderRecord> renderItem(ItemRunner& runner, const RenderJob& job, int threads) {
    const std::string film = (job.spectral ? (*job.spectral ? "-spectral" : "-rgb") : "") + job.variant;
    const std::string id = "render/" + job.scene.id + "/" + job.lens.facts.id + "/" + job.mode + film;
    const std::string image = "assets/renders/" + job.scene.id + "/" + job.lens.facts.id + "-" + job.mode + film + ".png";
    const ManifestItem* item =
        runner.run(id, "render " + job.lens.facts.id + " in " + job.scene.id + " (" + job.mode + film + ")", job.hash(), [&] {
            runner.countRender();
            const RenderOutput out = renderScene(job.settings(threads), {}, runner.cancel());
            writeSiteFile(runner.site(), image, encodePng(out.image, job.exposure()));
            RenderRecord r;
            r.image = image;
            r.mode = job.mode;
            r.width = out.image.width;
            r.height = out.image.height;
            r.spp = job.spp;
            r.fstop = job.fstop;
            r.exposure = job.exposure();
            r.setupSeconds = out.stats.setupSeconds;
            r.renderSeconds = out.stats.renderSeconds;
            r.cameraRays = out.stats.cameraRays;
            r.blockedCameraRays = out.stats.blockedCameraRays;
            r.raysTraced = out.stats.raysTraced;
            ManifestItem m;
            m.files = {image};
            m.data = renderRecordJson(r);
            return m;
        });
    if (!item) return std::nullopt;
    return renderRecordFromJson(item->data);
}

RgbaImage decodeSitePng(const fs::path& site, const std::string& relative) {
    return decodePng(readBinaryFile(site / relative));
}

double renderFstopFor(const LensEntry& lens, double requested) {
    return std::max(requested, lens.facts.analysis.at("fstop_min").get<double>());
}

}  // namespace

RenderPair buildRenderPair(ItemRunner& runner, const SceneSource& scene, const LensEntry& lens, const RenderPlan& plan,
                           const ReportOptions& o) {
    RenderPair pair;
    pair.lensId = lens.facts.id;
    const int height = heightFor(scene, plan.width);
    const double fstop = renderFstopFor(lens, o.renderFstop);
    const RenderJob accurate{scene, lens, "exact", plan.spp, plan.width, height, fstop, plan.ghostModel};
    const RenderJob approximate{scene, lens, "thick", plan.spp, plan.width, height, fstop, plan.ghostModel};
    const std::optional<RenderRecord> accurateRecord = renderItem(runner, accurate, o.threads);
    const std::optional<RenderRecord> approximateRecord = renderItem(runner, approximate, o.threads);
    const std::string label = "difference " + lens.facts.id + " in " + scene.id;
    if (!accurateRecord || !approximateRecord) {
        pair.problem = "the render failed (see the problems list)";
        runner.skip(label);
        return pair;
    }
    pair.accurate = *accurateRecord;
    pair.approximate = *approximateRecord;
    const std::string image = "assets/renders/" + scene.id + "/" + lens.facts.id + "-difference.png";
    InputsHash h = itemInputs("difference");
    h.add(accurate.hash()).add(approximate.hash()).add(kDifferenceGain);
    const ManifestItem* item = runner.run("difference/" + scene.id + "/" + lens.facts.id, label, h.hex(), [&] {
        const RgbaImage a = decodeSitePng(runner.site(), pair.accurate.image);
        const RgbaImage b = decodeSitePng(runner.site(), pair.approximate.image);
        const RgbaImage d = differenceImage(a, b, kDifferenceGain);
        writeSiteFile(runner.site(), image, encodePngRgba8(d.width, d.height, d.rgba.data()));
        ManifestItem m;
        m.files = {image};
        m.data = {{"rms", rmsDifference(a, b)}};
        return m;
    });
    if (item) {
        pair.differenceImage = image;
        pair.differenceGain = kDifferenceGain;
        pair.rmsDifference = item->data.at("rms").get<double>();
    } else {
        pair.problem = "the difference image failed (see the problems list)";
    }
    return pair;
}

ColourFringes buildColourFringes(ItemRunner& runner, const SceneSource& chart, const LensEntry& lens,
                                 const RenderPlan& plan, const ReportOptions& o) {
    ColourFringes c;
    const int height = heightFor(chart, plan.width);
    const double fstop = renderFstopFor(lens, o.renderFstop);
    c.fstop = fstop;
    const std::optional<RenderRecord> spectral =
        renderItem(runner, RenderJob{chart, lens, "exact", plan.spp, plan.width, height, fstop, plan.ghostModel, true}, o.threads);
    const std::optional<RenderRecord> rgb =
        renderItem(runner, RenderJob{chart, lens, "exact", plan.spp, plan.width, height, fstop, plan.ghostModel, false}, o.threads);
    if (spectral && rgb) {
        c.spectral = *spectral;
        c.rgb = *rgb;
    } else {
        c.problem = "the chart render failed (see the problems list)";
    }
    return c;
}

// The error of lower sample counts against the accurate render at the report's count, in both modes.
SpeedStudy buildSpeedStudy(ItemRunner& runner, const ReportScene& scene, const LensEntry& lens, const RenderPlan& plan,
                           const ReportOptions& o) {
    SpeedStudy study{scene.scene.id, lens.facts.id, plan.spp, {}};
    const RenderPair* reference = nullptr;
    for (const RenderPair& p : scene.pairs)
        if (p.lensId == lens.facts.id && p.problem.empty()) reference = &p;
    const int height = heightFor(scene.scene, plan.width);
    const double fstop = renderFstopFor(lens, o.renderFstop);
    const RenderJob referenceJob{scene.scene, lens, "exact", plan.spp, plan.width, height, fstop, plan.ghostModel};
    for (const char* mode : {"exact", "thick"})
        for (int spp : plan.speedSpps) {
            const std::string label = "speed study " + std::string(mode) + " at " + std::to_string(spp) + " spp";
            if (!reference) {
                runner.skip(label);
                continue;
            }
            const RenderJob job{scene.scene, lens, mode, spp, plan.width, height, fstop, plan.ghostModel};
            InputsHash h = itemInputs("speed");
            h.add(job.hash()).add(referenceJob.hash());
            const std::string id = "speed/" + scene.scene.id + "/" + lens.facts.id + "/" + mode + "/" + std::to_string(spp);
            const ManifestItem* item = runner.run(id, label, h.hex(), [&] {
                runner.countRender();
                const RenderOutput out = renderScene(job.settings(o.threads), {}, runner.cancel());
                const std::vector<std::uint8_t> png = encodePng(out.image, job.exposure());
                const double rms = rmsDifference(decodePng(png), decodeSitePng(runner.site(), reference->accurate.image));
                ManifestItem m;
                m.data = {{"seconds", out.stats.setupSeconds + out.stats.renderSeconds}, {"rms", rms}};
                return m;
            });
            if (item) study.points.push_back({mode, spp, item->data.at("seconds").get<double>(), item->data.at("rms").get<double>()});
        }
    if (reference)
        study.points.push_back({"thick", plan.spp, reference->approximate.setupSeconds + reference->approximate.renderSeconds,
                                reference->rmsDifference});
    return study;
}

namespace {

// The rms of each pixel's green minus its 5 x 5 neighbourhood's mean, over the image's mean green.
double relativeNoise(const RgbaImage& im) {
    double sum = 0, squares = 0, level = 0;
    int n = 0;
    const auto green = [&](int x, int y) { return double(im.rgba[(std::size_t(y) * im.width + x) * 4 + 1]); };
    for (int y = 2; y + 2 < im.height; ++y)
        for (int x = 2; x + 2 < im.width; ++x) {
            double local = 0;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) local += green(x + dx, y + dy) / 25;
            const double d = green(x, y) - local;
            sum += d;
            squares += d * d;
            level += green(x, y);
            ++n;
        }
    if (n == 0 || level <= 0) return 0;
    const double mean = sum / n;
    return std::sqrt(std::max(0.0, squares / n - mean * mean)) / (level / n);
}

}  // namespace

SensorLadder buildSensorLadder(ItemRunner& runner, const SceneSource& scene, const LensEntry& lens, const RenderPlan& plan,
                               const ReportOptions& o) {
    // A full-frame film of 4.35 um pixels, cropped around the rim of the sphere in focus as
    // dgauss.50mm frames it (docs/sensor.md).
    constexpr int kWidth = 8256, kHeight = 5504;
    const double halfX = 0.5 * plan.width / kWidth, halfY = 0.5 * plan.width * 2 / 3 / kHeight;
    const std::array<double, 4> crop = {0.415 - halfX, 0.415 + halfX, 0.575 - halfY, 0.575 + halfY};
    SensorLadder ladder{scene.id, lens.facts.id, {}, ""};
    const double fstop = renderFstopFor(lens, o.renderFstop);
    for (const double iso : kSensorLadderIsos) {
        const std::string isoText = formatNumber(iso);
        RenderJob job{scene, lens, "exact", plan.spp, kWidth, kHeight, fstop, plan.ghostModel};
        job.sensor = "iso=" + isoText + ",pitch=4.35";
        job.crop = crop;
        job.variant = "-iso" + isoText;
        const std::optional<RenderRecord> record = renderItem(runner, job, o.threads);
        if (!record) {
            ladder.problem = "a render of the ladder failed (see the problems list)";
            continue;
        }
        ladder.rungs.push_back({iso, *record, relativeNoise(decodeSitePng(runner.site(), record->image))});
    }
    return ladder;
}

}  // namespace lenslab
