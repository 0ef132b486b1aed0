#include "ReportPage.h"

namespace lenslab {

// Written for a reader who has done the course assignment: what lenslab computes and how, with
// the files that do it.
std::string algorithmsSectionHtml() {
    return R"html(<section id="algorithms">
<h2>How it works</h2>
<p>Everything optical is double precision, in millimetres, in the lens frame described under
<a href="#conventions">Conventions</a>. The lens table becomes a list of surfaces with signed
vertex positions, curvatures, the index on their film side and clear semi-diameters
(<code>optics/prescription/LensTable.cpp</code>, <code>optics/prescription/LensSystem.cpp</code>).</p>

<h3>Exact tracing and refraction</h3>
<p>A ray meets one surface at a time (<code>optics/trace/SurfaceStep.h</code>). The sphere is written relative
to its vertex, c|q|&sup2; + 2q<sub>z</sub> = 0, which stays exact as the curvature c goes to zero, so flat
surfaces and the stop need no special case. Both roots of the quadratic are formed without
cancellation; the hit is the root where the ray crosses the cap that contains the vertex in the
sense it travels, as light meets each surface from the medium before it (for a steep ray far outside a
strongly curved surface's rim the nearer root is where the line crosses back); a decentred or folded
system takes the nearest root on the cap, behind the ray too. A hit
beyond the clear semi-diameter blocks the ray (the stop's opening blocks it as "clipped by the stop").
Refraction is the vector form of Snell's law, t = &eta;d + (&eta; cos&theta;<sub>i</sub> &minus; cos&theta;<sub>t</sub>) n with
&eta; = n<sub>from</sub>/n<sub>to</sub>; a negative cos&sup2;&theta;<sub>t</sub> is total internal reflection. The same step, written on plain
scalars without branches, serves the single-ray trace (<code>optics/trace/ExactTrace.cpp</code>), both
directions (scene to film, film to scene), and a structure-of-arrays batch trace that the compiler
vectorises (<code>optics/trace/RayBatch.cpp</code>).</p>

<h3>Cardinal points</h3>
<p>There is no separate paraxial tracer. <code>optics/firstorder/FirstOrder.cpp</code> traces a ray parallel to the
axis at a small height h from the scene side: where it crosses the axis is F&prime;, where its extension
returns to height h is P&prime;, and the effective focal length is the distance from P&prime; to F&prime;. A ray from the
film side gives F and P the same way. Any of these quantities, measured with real rays, is
v(h) = v<sub>0</sub> + a h&sup2; + O(h&#8308;) by symmetry, so Richardson extrapolation, (4 v(h/2) &minus; v(h)) / 3, removes
the aberration term and leaves the paraxial value (<code>optics/trace/NearAxis.h</code>).</p>

<h3>Thick-lens model</h3>
<p>The approximate camera replaces the lens with its principal planes and focal length, Kolb's 4&times;4
projective matrix T = Translate(P&prime;) &middot; M &middot; Translate(&minus;P), where M leaves x, y, z and sets
w = 1 &minus; z/f (<code>optics/firstorder/ThickLens.cpp</code>). A ray is moved to the incoming principal plane; the
image of a point one focal length along it, kept in homogeneous form so that points on a focal plane
(w = 0) stay exact, gives the outgoing direction, which leaves the other principal plane at the
same height. The pupils stand in for the stop. The lens pages plot how far such rays land from the
exact ones on the F&prime; plane: that is the spherical aberration the thick lens ignores.</p>

<h3>Pupils</h3>
<p>The entrance pupil is the image of the stop through the elements in front of it, the exit pupil
its image through those behind (<code>optics/firstorder/Pupils.cpp</code>). A ray leaving the stop centre at a small
slope crosses the axis (extended) at the pupil; a ray leaving an off-axis stop point parallel to the
axis gives the pupil magnification. Both are extrapolated to the paraxial limit as above.</p>

<h3>f-number and stop opening</h3>
<p>The f-number is defined on the image side for an object at infinity: N = 1/(2 sin&theta;), &theta; the
angle of the marginal ray converging on F&prime; (<code>optics/firstorder/Aperture.cpp</code>). The widest the lens allows
is found by scanning and then bisecting the cone from F&prime; that still passes every surface with the
stop at its table size. For a requested N the marginal ray at &theta; = asin(1/(2N)) is traced from F&prime;
back to the stop plane; its height there is the stop radius.</p>

<h3>Focusing</h3>
<p><code>optics/firstorder/Focus.cpp</code> first places the film by the thick-lens formula, then refines it with real
rays: 64 meridional rays from the object point through equal-area rings of the entrance pupil are
traced exactly, and the film plane is the z minimising their RMS distance from the axis, a closed form
because each ray is a straight line after the lens. The difference between the two planes is
listed in every lens table; it is what a thick-lens focus gets wrong.</p>

<h3>Exit-pupil sampling</h3>
<p>The accurate camera aims rays from the film at the region of the rear-vertex plane through which
light actually passes (<code>optics/firstorder/ExitPupilBounds.cpp</code>). For a set of film radii that region (the
stop's image cut by element rims, the "cat's eye") is measured with the batch trace and stored as a
star-shaped polygon about its centroid, widened by 1%. By rotational symmetry a film point at any
angle uses the polygon of its radius, rotated; between measured radii the polygons are interpolated.
Samples are spread uniformly over the polygon's fan triangles, so few camera rays are blocked.</p>

<h3>Exposure weighting</h3>
<p>A camera ray from film point x&prime; to a point x&Prime; of the aiming plane carries the weight
L cos&theta;&prime; cos&theta;&Prime; / |x&Prime; &minus; x&prime;|&sup2; dA; for parallel planes a distance Z apart this is
cos&#8308;&theta; / Z&sup2;, times the sampled area (the inverse of the sample's density) and the exposure time
(<code>renderer/raytracer/cameras/RealisticCamera.cpp</code>). pbrt-v3's "simple weighting" instead divides by the weight at
the film centre. The approximate camera samples the exit pupil disc with the same weight.</p>

<h3>Relative illumination and distortion</h3>
<p>The illumination plots integrate the same cos&#8308;&theta; weight over the passing region seen from each
film radius, on a fine grid over the region's bounding box, and divide by the value at the centre;
the dashed curve leaves out cos&#8308;&theta; and shows vignetting alone (<code>optics/analysis/RelativeIllumination.cpp</code>).
Distortion compares the height at which the chief ray (the ray of a field angle &theta; that crosses the
stop centre, found by bisection on its height at the front vertex) meets the F&prime; plane with the
rectilinear f tan&theta; (<code>optics/analysis/Distortion.cpp</code>).</p>

<h3>This page</h3>
<p><code>report/</code> builds it: <code>BuildReport.cpp</code> runs every item through a cache keyed by a hash
of its inputs (lens and scene files, parameters, lenslab version, and a digest of the source code that
makes that kind of item), so an unchanged diagram or render is not made again and one made by older
code never reused; the plots are inline SVG written by <code>SvgPlot.cpp</code>.</p>
</section>
)html";
}

}  // namespace lenslab
