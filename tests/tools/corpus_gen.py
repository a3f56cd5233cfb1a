#!/usr/bin/env python3
"""Writes the differential corpus: small random scenes that together cover every surface type,
the material, pattern, texture and mixture families, instances and meshes, skies with and
without sun and closed rooms, rooms 3 m to 60 m deep, sensors near and far from the light.

Each scene is one family (its modifiers are the same in every variant, so the variants share
one compiled program) in a room of random size; the family fixes the sky. Each scene gets 12
upward -I sensors: 6 near its light (group 0), 6 far (group 1), and the options both
renderers run it with.

usage: corpus_gen.py OUT_DIR   (writes cNN.rad, cNN.pts, corpus.cal, corpus.dat, index.tsv;
       the shared files corpus.fnt, octa.rtm, blinds_klems.xml, film_t3.xml, box.oct are kept
       beside them, see tests/data/README.md)
"""
import os
import random
import sys

SKY_CLEAR = """void light solar 0 0 3 6.83e+06 6.83e+06 6.83e+06
solar source sun 0 0 4 -0.036458 -0.678528 0.733669 0.5
void brightfunc skyfunc 2 skybr skybright.cal 0 7 1 1.02e+01 2.21e+01 6.07e-01 -0.036458 -0.678528 0.733669
skyfunc glow sky_glow 0 0 4 0.99 0.99 1.1 0
sky_glow source sky 0 0 4 0 0 1 180
skyfunc glow ground_glow 0 0 4 1.4 0.9 0.6 0
ground_glow source ground 0 0 4 0 0 -1 180
"""
SKY_OVERCAST = """void brightfunc skyfunc 2 skybr skybright.cal 0 3 2 1.23e+01 1.91e+00
skyfunc glow sky_glow 0 0 4 1 1 1 0
sky_glow source sky 0 0 4 0 0 1 180
sky_glow source ground 0 0 4 0 0 -1 180
"""
SKY_UNIFORM = """void glow sky_glow 0 0 4 3 3 3 0
sky_glow source sky 0 0 4 0 0 1 180
void glow ground_glow 0 0 4 1 1 1 0
ground_glow source ground 0 0 4 0 0 -1 180
"""

CAL = """{ The differential corpus's own functions (tests/tools/corpus_gen.py). }
stripes = if(sin(7*Px) + 0.2, 1, 0.35);
wave_r = 0.6 + 0.3*sin(3*Px);
wave_g = 0.6;
wave_b = 0.6 + 0.3*cos(3*Py);
ripple_x = 0.08*sin(9*Py);
ripple_y = 0.08*cos(7*Px);
ripple_z = 0;
checker = if(sin(5*Px)*sin(5*Py), 1, 0);
ux = 1; uy = 0; uz = 0;
gloss(lx,ly,lz,om) = 0.3*max(0, lz)/PI;
shine(lx,ly,lz,om) = 0.05;
brtd(lx,ly,lz) = 0.02*max(0, lz);
one = 1;
tilt(dx, dy, dz, om) = 0.5 + 0.5*dz;
phi = atan2(Dy, Dx)/PI*180 + 180;
thz = acos(-Dz)/PI*180;
along = frac(Px/2);
scale(v) = v;
scale3(v, lx, ly, lz, om) = v;
bend_x = Dx; bend_y = Dy; bend_z = -Dz;
redirect = 0.6;
"""
# A 2-D distribution over (phi, theta) for brightdata and a 1-D ramp for the other *data types.
DAT = """2
0 360 5
0 180 5
1.0 0.9 0.7 0.4 0.1
1.2 1.0 0.6 0.3 0.1
0.8 0.8 0.7 0.5 0.2
1.1 1.0 0.8 0.4 0.1
1.0 0.9 0.7 0.4 0.1
"""
RAMP = """1
0 1 5
0.2 0.5 0.9 0.5 0.2
"""


def families():
    """(name, sky, options, modifiers, wall material, object materials, light kind)."""
    return [
        ("plain", SKY_CLEAR, "", """void plastic m_plastic 0 0 5 .6 .5 .4 .03 .05
void metal m_metal 0 0 5 .7 .7 .75 .8 .1""", "m_plastic", ["m_metal", "m_plastic"], "window"),
        ("trans", SKY_OVERCAST, "", """void plastic m_wall 0 0 5 .6 .6 .6 0 0
void trans m_trans 0 0 7 .7 .7 .7 .02 .05 .5 .3""", "m_wall", ["m_trans"], "window"),
        ("dielectric", SKY_CLEAR, "", """void plastic m_wall 0 0 5 .5 .5 .5 0 0
void glass m_glass 0 0 3 .86 .86 .86
void dielectric m_water 0 0 5 .95 .97 .99 1.33 0
void interface m_iface 0 0 8 .98 .98 .98 1.5 .99 .99 .99 1.0""", "m_wall",
         ["m_water", "m_iface"], "glazed"),
        ("mirror", SKY_UNIFORM, "", """void plastic m_wall 0 0 5 .5 .5 .5 0 0
void mirror m_mirror 0 0 3 .85 .85 .85
void metal m_chrome 0 0 5 .8 .8 .8 1 0""", "m_wall", ["m_mirror", "m_chrome"], "panel"),
        ("aniso", None, "", """void plastic m_wall 0 0 5 .55 .55 .5 0 0
void plastic2 m_p2 4 ux uy uz corpus.cal 0 6 .5 .3 .2 .05 .05 .2
void metal2 m_m2 4 ux uy uz corpus.cal 0 6 .7 .7 .7 .9 .05 .3
void trans2 m_t2 4 ux uy uz corpus.cal 0 8 .6 .6 .6 .03 .1 .2 .4 .2
void ashik2 m_a2 4 ux uy uz corpus.cal 0 8 .3 .3 .3 .2 .2 .2 50 200""", "m_wall",
         ["m_p2", "m_m2", "m_t2", "m_a2"], "panel"),
        ("func", SKY_OVERCAST, "", """void plastic m_wall 0 0 5 .6 .6 .6 0 0
void plasfunc m_pf 2 gloss corpus.cal 0 5 .5 .4 .3 .05 .1
void metfunc m_mf 2 gloss corpus.cal 0 5 .7 .6 .5 .5 .1
void transfunc m_tf 2 gloss corpus.cal 0 6 .6 .6 .6 .03 .4 .3
void BRTDfunc m_brtd 10 0 0 0 0 0 0 brtd brtd brtd corpus.cal 0 9 .3 .3 .3 .3 .3 .3 0 0 0""",
         "m_wall", ["m_pf", "m_mf", "m_tf", "m_brtd"], "window"),
        ("data", None, "", """void plastic m_wall 0 0 5 .6 .6 .6 0 0
void plasdata m_pd 4 scale3 ramp.dat corpus.cal tilt 0 4 .5 .5 .4 .05
void metdata m_md 4 scale3 ramp.dat corpus.cal tilt 0 4 .7 .7 .6 .5
void transdata m_td 4 scale3 ramp.dat corpus.cal tilt 0 6 .6 .6 .6 .03 .4 .3""", "m_wall",
         ["m_pd", "m_md", "m_td"], "sphere"),
        ("patterns", SKY_CLEAR, "", """void brightfunc p_stripes 2 stripes corpus.cal 0 0
p_stripes plastic m_wall 0 0 5 .6 .6 .6 0 0
void colorfunc p_wave 4 wave_r wave_g wave_b corpus.cal 0 0
p_wave plastic m_wave 0 0 5 .7 .7 .7 0 0
void colordata p_cdata 8 scale scale scale ramp.dat ramp.dat ramp.dat corpus.cal along 0 0
p_cdata plastic m_cdata 0 0 5 .7 .7 .7 0 0
void brighttext p_text 4 corpus.fnt . LOIL IOLO 0 11 0 0 1 .25 0 0 0 0 -.3 1 .3
p_text plastic m_text 0 0 5 .6 .6 .6 0 0""", "m_wall", ["m_wave", "m_cdata", "m_text"], "window"),
        ("luminaire", None, "", """void plastic m_wall 0 0 5 .6 .6 .6 0 0
void brightdata p_dist 5 scale corpus.dat corpus.cal phi thz 0 0
p_dist light m_lum 0 0 3 30 30 30
void colortext p_ctext 4 corpus.fnt . LOIL IOLO 0 15 0 0 1 .25 0 0 0 0 -.3 .9 .5 .2 .2 .4 .8
p_ctext plastic m_ctext 0 0 5 .7 .7 .7 0 0""", "m_wall", ["m_ctext"], "brightdata"),
        ("textures", SKY_UNIFORM, "", """void texfunc t_ripple 4 ripple_x ripple_y ripple_z corpus.cal 0 0
t_ripple plastic m_wall 0 0 5 .6 .6 .6 .04 .05
void texdata t_data 8 scale scale scale ramp.dat ramp.dat ramp.dat corpus.cal along 0 0
t_data metal m_tmetal 0 0 5 .7 .7 .7 .8 .05""", "m_wall", ["m_tmetal"], "window"),
        ("mixtures", SKY_OVERCAST, "", """void plastic m_red 0 0 5 .6 .1 .1 0 0
void plastic m_blue 0 0 5 .1 .1 .6 .02 .05
void mixfunc m_wall 4 m_red m_blue checker corpus.cal 0 0
void mixdata m_mdata 6 m_red m_blue scale ramp.dat corpus.cal along 0 0
void mixtext m_mtext 5 m_red m_blue corpus.fnt . LOIL 0 9 0 0 1 .25 0 0 0 0 -.3""", "m_wall",
         ["m_mdata", "m_mtext"], "window"),
        ("sources", None, "", """void plastic m_wall 0 0 5 .6 .6 .6 0 0
void spotlight m_spot 0 0 7 800 800 800 40 0 0 -1
void illum m_illum 0 0 3 20 20 20
void glow m_glowball 0 0 4 5 4 3 .5
void metal m_metal 0 0 5 .7 .7 .7 .6 .08""", "m_wall", ["m_metal"], "spot"),
        ("media", SKY_UNIFORM, "-me .02 .02 .03 -ma .6 .6 .6 -mg .2", """void plastic m_wall 0 0 5 .6 .6 .6 0 0
void plastic m_box 0 0 5 .5 .4 .3 0 0
void antimatter m_cut 1 m_box 0 0""", "m_wall", ["m_box", "m_cut"], "panel"),
        ("bsdf", SKY_CLEAR, "", """void plastic m_wall 0 0 5 .6 .6 .6 0 0
void BSDF m_blinds 6 0 blinds_klems.xml 0 0 1 . 0 0
void BSDF m_film 6 0 film_t3.xml 0 0 1 . 0 0""", "m_wall", ["m_film"], "bsdfwindow"),
        ("geometry", SKY_OVERCAST, "", """void plastic m_wall 0 0 5 .6 .6 .6 0 0
void plastic m_grey 0 0 5 .5 .5 .5 .02 .1
void metal m_steel 0 0 5 .6 .6 .65 .9 .2""", "m_wall", ["m_grey", "m_steel"], "window"),
        ("prism", SKY_CLEAR, "", """void plastic m_wall 0 0 5 .6 .6 .6 0 0
void prism1 m_prism 5 redirect bend_x bend_y bend_z corpus.cal 0 0
void mist m_mist 0 0 3 .05 .05 .05""", "m_wall", ["m_wall"], "prism"),
    ]


class Scene:
    def __init__(self, rng):
        self.rng = rng
        self.lines = []
        self.n = 0

    def poly(self, mat, pts):
        self.n += 1
        flat = "  ".join("%.4g %.4g %.4g" % p for p in pts)
        self.lines.append("%s polygon s%d 0 0 %d %s" % (mat, self.n, 3 * len(pts), flat))

    def prim(self, mat, kind, args):
        self.n += 1
        self.lines.append("%s %s s%d 0 0 %d %s" % (mat, kind, self.n, len(args),
                                                   " ".join("%.4g" % a for a in args)))

    def box(self, mat, x0, y0, z0, x1, y1, z1):
        """A closed box facing outwards."""
        p = lambda i, j, k: ((x0, x1)[i], (y0, y1)[j], (z0, z1)[k])
        for f in ([p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0)],
                  [p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)],
                  [p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)],
                  [p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0)],
                  [p(0, 0, 0), p(0, 0, 1), p(0, 1, 1), p(0, 1, 0)],
                  [p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)]):
            self.poly(mat, f)


def room(sc, wall, w, d, h, opening, glazing):
    """Inward-facing room [0,w] x [0,d] x [0,h]; the wall at y = 0 has an opening (0.9 to
    h - 0.3 m high over the middle 80%) when `opening`, filled with `glazing` if given."""
    sc.poly(wall, [(0, 0, 0), (w, 0, 0), (w, d, 0), (0, d, 0)])
    sc.poly(wall, [(0, 0, h), (0, d, h), (w, d, h), (w, 0, h)])
    sc.poly(wall, [(0, d, 0), (w, d, 0), (w, d, h), (0, d, h)])
    sc.poly(wall, [(0, 0, 0), (0, d, 0), (0, d, h), (0, 0, h)])
    sc.poly(wall, [(w, 0, 0), (w, 0, h), (w, d, h), (w, d, 0)])
    if not opening:
        sc.poly(wall, [(0, 0, 0), (0, 0, h), (w, 0, h), (w, 0, 0)])
        return
    x0, x1, z0, z1 = 0.1 * w, 0.9 * w, 0.9, h - 0.3
    for q in ([(0, 0, 0), (0, 0, z0), (w, 0, z0), (w, 0, 0)],
              [(0, 0, z1), (0, 0, h), (w, 0, h), (w, 0, z1)],
              [(0, 0, z0), (0, 0, z1), (x0, 0, z1), (x0, 0, z0)],
              [(x1, 0, z0), (x1, 0, z1), (w, 0, z1), (w, 0, z0)]):
        sc.poly(wall, q)
    if glazing:
        sc.poly(glazing, [(x0, 0, z0), (x0, 0, z1), (x1, 0, z1), (x1, 0, z0)])


def make(index, fam, rng):
    name, sky, opts, mods, wall, objmats, light = fam
    sc = Scene(rng)
    w = rng.uniform(3, 12)
    d = rng.choice([rng.uniform(3, 8), rng.uniform(8, 25), rng.uniform(25, 60)])
    h = rng.uniform(2.5, 3.6)
    out = ["# corpus scene %d: family %s, %.2f x %.2f x %.2f m" % (index, name, w, d, h)]
    if sky:
        out.append(sky)
    out.append(mods)
    window = light in ("window", "glazed", "bsdfwindow", "prism")
    glazing = {"glazed": "m_glass", "bsdfwindow": "m_blinds", "prism": "m_prism"}.get(light)
    room(sc, wall, w, d, h, window, glazing)
    near = (w / 2, 1.5)  # the light's side
    if light in ("panel", "sphere", "spot", "brightdata"):
        # Electric light near y = 1.5 (a closed room, or beside the window for the mirror's).
        ly = rng.uniform(1.2, 2.0)
        near = (w / 2, ly)
        if light in ("panel",):
            out.append("void light m_panel 0 0 3 40 40 40")
            sc.poly("m_panel", [(w / 2 - .3, ly - .3, h - .01), (w / 2 - .3, ly + .3, h - .01),
                                (w / 2 + .3, ly + .3, h - .01), (w / 2 + .3, ly - .3, h - .01)])
        elif light == "sphere":
            out.append("void light m_bulb 0 0 3 200 180 150")
            sc.prim("m_bulb", "sphere", [w / 2, ly, h - .4, .08])
            out.append("void light m_ringlamp 0 0 3 60 60 60")
            sc.prim("m_ringlamp", "ring", [w / 2, d * .7, h - .01, 0, 0, -1, 0, .15])
        elif light == "spot":
            sc.prim("m_spot", "ring", [w / 2, ly, h - .02, 0, 0, -1, 0, .1])
            sc.poly("m_illum", [(.2, d * .6, h - .01), (.2, d * .6 + .6, h - .01),
                                (.8, d * .6 + .6, h - .01), (.8, d * .6, h - .01)])
            out.append("void light m_tube 0 0 3 15 15 15")
            sc.prim("m_tube", "cylinder", [w * .3, d * .8, h - .2, w * .7, d * .8, h - .2, .03])
            sc.prim("m_glowball", "sphere", [w * .8, d * .3, 1.5, .1])
        elif light == "brightdata":
            sc.poly("m_lum", [(w / 2 - .2, ly - .2, h - .01), (w / 2 - .2, ly + .2, h - .01),
                              (w / 2 + .2, ly + .2, h - .01), (w / 2 + .2, ly - .2, h - .01)])
    if name == "mirror":
        sc.poly("m_mirror", [(w - .01, d * .3, .5), (w - .01, d * .3 + 1.2, .5),
                             (w - .01, d * .3 + 1.2, 1.8), (w - .01, d * .3, 1.8)])
    if name == "prism":
        # A mist volume under the window (a box of m_mist).
        sc.box("m_mist", w * .3, .3, .2, w * .7, 1.3, 1.2)
    # Objects: two to four of the family's materials on random surface types.
    kinds = ["sphere", "cylinder", "cone", "box", "ring", "cup", "tube", "bubble"]
    for k in range(rng.randint(2, 4)):
        mat = objmats[k % len(objmats)]
        x, y = rng.uniform(.8, w - .8), rng.uniform(1.5, max(2.0, d - 1))
        s = rng.uniform(.15, .4)
        kind = kinds[(index + k) % len(kinds)]
        if name == "media":
            # A box with a spherical bite taken out of its corner by antimatter.
            sc.box("m_box", x - s, y - s, 0, x + s, y + s, 2 * s)
            sc.prim("m_cut", "sphere", [x + s, y - s, 2 * s, s * .8])
        elif kind == "sphere" or kind == "bubble":
            sc.prim(mat, kind, [x, y, s + .3, s])
        elif kind in ("cylinder", "tube"):
            sc.prim(mat, kind, [x, y, 0, x, y, 2 * s, s * .6])
        elif kind in ("cone", "cup"):
            sc.prim(mat, kind, [x, y, 0, x, y, 2 * s, s, .05])
        elif kind == "ring":
            sc.prim(mat, kind, [x, y, .6, 0, .3, 1, .05, s])
        else:
            sc.box(mat, x - s, y - s, 0, x + s, y + s, 2 * s)
    if name == "geometry":
        out.append("void instance i_box 1 box.oct 0 0")
        out.append("void mesh i_octa 1 octa.rtm 0 0")
        for k in range(2):
            x, y = rng.uniform(1, w - 1), rng.uniform(2, max(2.5, d - 1))
            sc.lines.append("void instance b%d 7 box.oct -rz %d -t %.3f %.3f 0 0 0" %
                            (k, rng.randint(0, 90), x, y))
            sc.lines.append("m_steel mesh o%d 7 octa.rtm -s .3 -t %.3f %.3f .5 0 0" %
                            (k, x + .8 if x + .8 < w else x - .8, y))
        out = [l for l in out if not l.startswith("void instance i_") and
               not l.startswith("void mesh i_")]
    out.extend(sc.lines)
    # Sensors: 6 near the light (within 0.6-2.5 m), 6 far (the back half).
    pts = []
    for k in range(6):
        pts.append((min(max(near[0] + rng.uniform(-1.5, 1.5), .3), w - .3),
                    min(max(near[1] + rng.uniform(.6, 2.5), .3), d - .3), .8))
    for k in range(6):
        pts.append((rng.uniform(.3, w - .3), rng.uniform(max(d / 2, .3), d - .3), .8))
    return "\n".join(out) + "\n", "".join("%.4f %.4f %.4f 0 0 1\n" % p for p in pts), opts


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "corpus.cal"), "w") as f:
        f.write(CAL)
    with open(os.path.join(out, "corpus.dat"), "w") as f:
        f.write(DAT)
    with open(os.path.join(out, "ramp.dat"), "w") as f:
        f.write(RAMP)
    with open(os.path.join(out, "box.rad"), "w") as f:
        f.write("# the corpus's instance (frozen into box.oct by oconv -f)\n"
                "void plastic b_wood 0 0 5 .45 .32 .2 .02 .05\n")
        b = Scene(None)
        b.box("b_wood", 0, 0, 0, .6, .4, .7)
        f.write("\n".join(b.lines) + "\n")
    rng = random.Random(54)
    fams = families()
    index = []
    n = 0
    for variant in range(4):
        for fam in fams:
            rad, pts, opts = make(n, fam, rng)
            with open(os.path.join(out, "c%02d.rad" % n), "w") as f:
                f.write(rad)
            with open(os.path.join(out, "c%02d.pts" % n), "w") as f:
                f.write(pts)
            index.append("c%02d\t%s\t%s\n" % (n, fam[0], opts))
            n += 1
    with open(os.path.join(out, "index.tsv"), "w") as f:
        f.write("# scene\tfamily\textra options\n")
        f.writelines(index)


if __name__ == "__main__":
    main()
