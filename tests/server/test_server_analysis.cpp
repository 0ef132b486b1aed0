// GET /api/lenses/{id}/analysis on the real `lenslab serve`: the analysis JSON with its keys, with
// views=html the page's views of it too, and 400 naming the parameter for lists that are malformed
// or too long; GET /api/lenses/{id}/ghosts.
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
    EXPECT_FALSE(ok.body.contains("views"));  // only when asked for

    // views=html: the same analysis with the page's settings, tables and plots, two fields' worth.
    const Reply views = get(c, "/api/lenses/dgauss.50mm/analysis?fstop=4&focus=inf&wavelengths=F,d,C&fields=0,1&views=html");
    ASSERT_EQ(views.status, 200) << views.raw.substr(0, 400);
    json without = views.body;
    without.erase("views");
    EXPECT_EQ(without, ok.body);
    std::vector<std::string> names;
    for (const json& plot : views.body["views"]["plots"]) {
        names.push_back(plot["name"]);
        EXPECT_EQ(plot["svg"].get<std::string>().rfind("<svg", 0), 0u) << names.back();
        EXPECT_FALSE(plot["caption"].get<std::string>().empty()) << names.back();
    }
    EXPECT_EQ(names, (std::vector<std::string>{"spot-field-1", "mtf-field-1", "fans-field-1", "spot-field-2", "mtf-field-2", "fans-field-2",
                                               "field-curvature", "distortion", "relative-illumination", "chromatic-focal-shift"}));
    EXPECT_NE(views.body["views"]["settings_html"].get<std::string>().find("data-json=\"/fstop\""), std::string::npos);
    EXPECT_NE(views.body["views"]["tables_html"].get<std::string>().find("data-json=\"/fields/1/polychromatic/rms_radius_mm\""),
              std::string::npos);

    const std::string base = "/api/lenses/dgauss.50mm/analysis?";
    const std::string seventeen = "0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0";
    for (const auto& [query, parameter] : std::vector<std::pair<std::string, std::string>>{
             {"wavelengths=F,x", "wavelengths"}, {"wavelengths=150", "wavelengths"}, {"fields=" + seventeen, "fields"},
             {"fields=0,2", "fields"}, {"fields=0,,1", "fields"}, {"fstop=abc", "fstop"}, {"max_frequency=-1", "max_frequency"},
             {"views=svg", "views"}}) {
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

// The image plane and the reference point change the answer, so a cached answer for one must not
// be served for another: the paraxial plane sits where the paraxial trace puts it, the film plane
// elsewhere, and the chief-ray reference moves the spot's points off the centroid.
TEST(ServerAnalysis, ImagePlaneAndReferenceAreHeldApartByTheCache) {
    TempDir data;
    ServerProcess server(LENSLAB_BINARY, data.path() + "/data");
    auto c = server.client();
    const std::string base = "/api/lenses/dgauss.50mm/analysis?fstop=2.8&wavelengths=d&fields=0,1";
    const Reply film = get(c, base + "&image_plane=film");
    const Reply paraxial = get(c, base + "&image_plane=paraxial");
    const Reply filmAgain = get(c, base + "&image_plane=film");
    ASSERT_EQ(film.status, 200) << film.raw.substr(0, 400);
    ASSERT_EQ(paraxial.status, 200) << paraxial.raw.substr(0, 400);
    EXPECT_EQ(film.body["image_plane"], "film");
    EXPECT_EQ(paraxial.body["image_plane"], "paraxial");
    EXPECT_NE(film.body["image_z"].get<double>(), paraxial.body["image_z"].get<double>());
    EXPECT_EQ(film.raw, filmAgain.raw);

    const Reply chief = get(c, base + "&reference=chief");
    ASSERT_EQ(chief.status, 200) << chief.raw.substr(0, 400);
    EXPECT_EQ(chief.body["reference"], "chief");
    const auto rms = [](const Reply& r) { return r.body["fields"][1]["spots"][0]["rms_radius_mm"].get<double>(); };
    EXPECT_GT(rms(chief), rms(film));  // about the chief ray is never smaller than about the centroid
}
