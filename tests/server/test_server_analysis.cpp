// GET /api/lenses/{id}/analysis on the real `lenslab serve`: the analysis JSON with its keys, and
// 400 naming the parameter for lists that are malformed or too long; GET /api/lenses/{id}/ghosts.
#include <gtest/gtest.h>

#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

TEST(ServerAnalysis, ServesTheAnalysisAndRefusesBadListsNamingThem) {
    TempDir data;
    ServerProcess server(LENSLAB_BINARY, data.path() + "/data");
    auto c = server.client();
    const Reply ok = get(c, "/api/lenses/dgauss.50mm/analysis?fstop=4&focus=inf&wavelengths=F,d,C&fields=0,1");
    ASSERT_EQ(ok.status, 200) << ok.raw.substr(0, 400);
    EXPECT_EQ(ok.body["id"], "dgauss.50mm");
    EXPECT_EQ(ok.body["wavelengths_nm"].size(), 3u);
    ASSERT_EQ(ok.body["fields"].size(), 2u);
    const json& edge = ok.body["fields"][1];
    EXPECT_GT(edge["field_deg"].get<double>(), 0);
    for (const char* key : {"wavelength_nm", "rms_radius_mm", "geo_radius_mm", "centroid_mm", "points"})
        EXPECT_TRUE(edge["spots"][0].contains(key)) << key;
    for (const char* key : {"sagittal", "tangential"}) {
        EXPECT_EQ(edge["mtf"]["diffraction"][key].size(), edge["mtf"]["frequencies_lpmm"].size()) << key;
        EXPECT_EQ(edge["mtf"]["geometric"][key].size(), edge["mtf"]["frequencies_lpmm"].size()) << key;
    }
    EXPECT_TRUE(edge["mtf"].contains("diffraction_limit"));
    for (const char* key : {"distortion_percent", "chromatic_focal_shift_mm", "field_curvature", "relative_illumination", "ray_fans"})
        EXPECT_TRUE(ok.body.contains(key)) << key;
    EXPECT_EQ(ok.body["distortion_percent"].size(), 2u);
    EXPECT_EQ(ok.body["chromatic_focal_shift_mm"].size(), 3u);

    const std::string base = "/api/lenses/dgauss.50mm/analysis?";
    const std::string seventeen = "0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0";
    for (const auto& [query, parameter] : std::vector<std::pair<std::string, std::string>>{
             {"wavelengths=F,x", "wavelengths"}, {"wavelengths=200", "wavelengths"}, {"fields=" + seventeen, "fields"},
             {"fields=0,2", "fields"}, {"fields=0,,1", "fields"}, {"fstop=abc", "fstop"}, {"max_frequency=-1", "max_frequency"}}) {
        const Reply bad = get(c, base + query);
        EXPECT_EQ(bad.status, 400) << query << " " << bad.raw;
        EXPECT_NE(bad.body.value("error", std::string()).find(parameter), std::string::npos) << query << " " << bad.raw;
    }
    EXPECT_EQ(get(c, "/api/lenses/no-such-lens/analysis").status, 404);

    // The ghost analysis: every two-reflection path of dgauss.50mm (10 reflecting surfaces) at the
    // settings asked, brightest first; the lens settings' errors are optics' as elsewhere.
    const Reply ghosts = get(c, "/api/lenses/dgauss.50mm/ghosts?fstop=4&focus=inf");
    ASSERT_EQ(ghosts.status, 200) << ghosts.raw.substr(0, 400);
    EXPECT_EQ(ghosts.body["id"], "dgauss.50mm");
    EXPECT_EQ(ghosts.body["reflecting_surfaces"], 10);
    ASSERT_EQ(ghosts.body["ghosts"].size(), 45u);
    const json& first = ghosts.body["ghosts"][0];
    for (const char* key : {"surfaces", "reflectance", "focus_z", "focus_from_film_mm", "blur_diameter_mm", "field_scale",
                            "energy", "relative_intensity", "focused"})
        EXPECT_TRUE(first.contains(key)) << key;
    EXPECT_GE(first["relative_intensity"].get<double>(), ghosts.body["ghosts"][44]["relative_intensity"].get<double>());
    EXPECT_EQ(get(c, "/api/lenses/dgauss.50mm/ghosts?fstop=0.5").status, 422);
    EXPECT_EQ(get(c, "/api/lenses/no-such-lens/ghosts").status, 404);
}
