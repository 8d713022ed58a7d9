#!/usr/bin/env python3
"""The bench's copy of the shared bench's peers/mitsuba_whitted.py (ray.bench.Mesh1mPeers copies it next
to its Mitsuba translation of mesh1m), with area lights: an area emitter (a `rectangle` with an `area`
emitter) is sampled as the project's AreaLight with its default grid sampler is, at the centres of
n x n cells (integrator parameter `area_samples`, n, default 4), each sample a point light of
I / n^2 falling off as r^-2 and shadowed on its own, I = radiance x area: Mitsuba's own sample weight
(radiance x area x cos_light / r^2 for a uniform point on the rectangle) with the emitter's cosine
divided out, since the project's area light is n^2 isotropic points, not a Lambertian emitter. Point
emitters are handled as before. The rest is the original:

Render a translated scene (peers/build/mitsuba/NAME.xml) with Mitsuba 3 using a
Whitted integrator and a material plugin that implement the project's shading spec exactly:

    L = k_a I_a + sum_lights [k_d (I/r^2) max(0,n.l) + k_s (I/r^2) max(0,n.h)^p] + k_m L_mirror

one shadow ray per light (cast where the light's term is non-zero), mirror recursion up to
MaxDepth bounces, BGColor on a miss, the normal turned to face the ray.

    python peers/mitsuba_whitted.py VARIANT peers/build/mitsuba/NAME.xml OUT.png

VARIANT: scalar_rgb or llvm_ad_rgb. Prints load / render seconds on stderr.
"""
import sys
import time

t0 = time.perf_counter()
import drjit as dr
import mitsuba as mi

mi.set_variant(sys.argv[1])


def _vec(props, name, default=(0.0, 0.0, 0.0)):
    if name in props:
        v = props.get(name)
        return [float(v[0]), float(v[1]), float(v[2])]
    return list(default)


class WhittedMat(mi.BSDF):
    """k_d, k_s, p, k_m; k_a is returned by eval_diffuse_reflectance (used for the ambient term)."""

    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        self.ka = mi.Color3f(*_vec(props, "ka"))
        self.kd = mi.Color3f(*_vec(props, "kd"))
        self.ks = mi.Color3f(*_vec(props, "ks"))
        self.p = mi.Float(props.get("p", 1.0))
        self.km = mi.Color3f(props.get("km", 0.0))
        both = mi.BSDFFlags.FrontSide | mi.BSDFFlags.BackSide
        self.m_components = [mi.BSDFFlags.DeltaReflection | both, mi.BSDFFlags.GlossyReflection | both]
        self.m_flags = self.m_components[0] | self.m_components[1]

    def sample(self, ctx, si, sample1, sample2, active=True):
        bs = mi.BSDFSample3f()
        bs.wo = mi.reflect(si.wi)
        bs.pdf = mi.Float(1.0)
        bs.eta = mi.Float(1.0)
        bs.sampled_type = mi.UInt32(+mi.BSDFFlags.DeltaReflection)
        bs.sampled_component = mi.UInt32(0)
        return (bs, mi.Color3f(self.km))

    def eval(self, ctx, si, wo, active=True):
        s = dr.select(si.wi.z < 0, -1.0, 1.0)          # face the ray
        nl = wo.z * s
        h = dr.normalize(si.wi + wo)
        nh = dr.maximum(h.z * s, 0.0)
        return self.kd * dr.maximum(nl, 0.0) + self.ks * dr.power(nh, self.p)

    def pdf(self, ctx, si, wo, active=True):
        return mi.Float(0.0)

    def eval_pdf(self, ctx, si, wo, active=True):
        return self.eval(ctx, si, wo, active), mi.Float(0.0)

    def eval_diffuse_reflectance(self, si, active=True):
        return mi.Color3f(self.ka)

    def traverse(self, callback):
        pass

    def parameters_changed(self, keys):
        pass

    def to_string(self):
        return "WhittedMat"


class Whitted(mi.SamplingIntegrator):
    def __init__(self, props):
        mi.SamplingIntegrator.__init__(self, props)
        self.max_depth = int(props.get("max_depth", 10))
        self.area_samples = int(props.get("area_samples", 4))
        self.ambient = mi.Color3f(*_vec(props, "ambient"))
        self.bg = mi.Color3f(*_vec(props, "background"))

    def light_samples(self, e):
        """The 2D samples an emitter is sampled at, with the weight of each: one at (0.5, 0.5) for a
        point light; the n x n cell centres for an area emitter, each weighted 1 / n^2."""
        if not mi.has_flag(e.flags(), mi.EmitterFlags.Surface):
            return [(0.5, 0.5)], None
        n = self.area_samples
        return [((i + 0.5) / n, (j + 0.5) / n) for j in range(n) for i in range(n)], 1.0 / (n * n)

    def sample(self, scene, sampler, ray_, medium=None, active=True):
        if dr.is_jit_v(mi.Float):
            return self.sample_jit(scene, ray_, active)
        return self.sample_scalar(scene, ray_)

    def sample_scalar(self, scene, ray_):
        """scalar_* variants: one ray at a time, plain Python control flow (a null BSDF
        pointer on a miss must never be called in scalar mode)."""
        ctx = mi.BSDFContext()
        L = mi.Color3f(0.0)
        beta = mi.Color3f(1.0)
        ray = mi.Ray3f(ray_)
        for depth in range(self.max_depth + 1):
            si = scene.ray_intersect(ray)
            if not si.is_valid():
                L += beta * self.bg
                break
            bsdf = si.bsdf(ray)
            L += beta * bsdf.eval_diffuse_reflectance(si) * self.ambient
            for e in scene.emitters():
                uvs, w = self.light_samples(e)
                for uv in uvs:
                    ds, spec = e.sample_direction(si, mi.Point2f(*uv))
                    if w is not None:                       # isotropic points: no emitter cosine
                        cos_l = -dr.dot(ds.n, ds.d)
                        spec = spec * (w / cos_l) if cos_l > 0.0 else mi.Color3f(0.0)
                    f = bsdf.eval(ctx, si, si.to_local(ds.d))
                    if dr.max(f) > 0.0 and not scene.ray_test(si.spawn_ray_to(ds.p)):
                        L += beta * f * spec
            bs, w = bsdf.sample(ctx, si, 0.0, mi.Point2f(0.0))
            if not dr.max(w) > 0.0:
                break
            beta *= w
            ray = si.spawn_ray(si.to_world(bs.wo))
        return (L, True, [])

    @dr.syntax
    def sample_jit(self, scene, ray_, active):
        ctx = mi.BSDFContext()
        emitters = scene.emitters()
        L = mi.Color3f(0.0)
        beta = mi.Color3f(1.0)
        ray = mi.Ray3f(ray_)
        depth = mi.UInt32(0)
        active = mi.Bool(active)
        while active:
            si = scene.ray_intersect(ray, active)
            hit = active & si.is_valid()
            L += dr.select(active & ~hit, beta * self.bg, 0.0)
            bsdf = si.bsdf(ray)
            L += dr.select(hit, beta * bsdf.eval_diffuse_reflectance(si, hit) * self.ambient, 0.0)
            for e in emitters:
                uvs, w = self.light_samples(e)
                for uv in uvs:
                    ds, spec = e.sample_direction(si, mi.Point2f(uv[0], uv[1]), hit)
                    if w is not None:                       # isotropic points: no emitter cosine
                        cos_l = -dr.dot(ds.n, ds.d)
                        spec = dr.select(cos_l > 0.0, spec * (w / cos_l), 0.0)
                    f = bsdf.eval(ctx, si, si.to_local(ds.d), hit)
                    lit = hit & (dr.max(f) > 0.0)
                    occluded = scene.ray_test(si.spawn_ray_to(ds.p), lit)
                    L += dr.select(lit & ~occluded, beta * f * spec, 0.0)
            bs, w = bsdf.sample(ctx, si, 0.0, mi.Point2f(0.0), hit)
            beta *= w
            depth += 1
            active = hit & (dr.max(w) > 0.0) & (depth <= self.max_depth)
            ray = si.spawn_ray(si.to_world(bs.wo))
        return (L, mi.Bool(True), [])

    def aov_names(self):
        return []

    def to_string(self):
        return "Whitted"


mi.register_bsdf("whittedmat", lambda props: WhittedMat(props))
mi.register_integrator("whitted", lambda props: Whitted(props))


def main():
    xml, out = sys.argv[2], sys.argv[3]
    t1 = time.perf_counter()
    scene = mi.load_file(xml)
    t2 = time.perf_counter()
    img = mi.render(scene)
    dr.eval(img)
    dr.sync_thread()
    t3 = time.perf_counter()
    bmp = mi.Bitmap(img).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.UInt8, srgb_gamma=False)
    bmp.write(out)
    t4 = time.perf_counter()
    print("mitsuba %s %s: import %.2fs load %.2fs render %.2fs write %.2fs"
          % (sys.argv[1], xml, t1 - t0, t2 - t1, t3 - t2, t4 - t3), file=sys.stderr)


if __name__ == "__main__":
    main()
