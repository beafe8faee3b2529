/* shadowpoint: pointlight whose light is stopped by six shadow maps made from the light's
   position, one looking along each axis of world space: sfpx along +x, sfnx along -x, sfpy,
   sfny, sfpz, sfnz likewise (PRMan's parameter names). A point is looked up in the map of the
   axis its direction from the light lies closest to (L's largest world component, as a cube
   map's faces are chosen), filtered as in shadowspot: samples percentage-closer samples,
   widened by blur (a fraction of the map) and width (times the shaded point's footprint);
   bias < 0 leaves the depth offset to the renderer. A map left "" casts no shadow on its
   side. */

/* The fraction of p in shadow in the map `name` (0 without one). */
float shadowpoint_fraction(string name; point p; float samples, blur, width, bias)
{
    float fraction = 0;
    if (name != "")
        fraction = shadow(name, p, "samples", samples, "blur", blur, "width", width,
                          "bias", bias);
    return fraction;
}

light shadowpoint(float intensity = 1; color lightcolor = 1;
                  point from = point "shader" (0, 0, 0);
                  string sfpx = "", sfnx = "", sfpy = "", sfny = "", sfpz = "", sfnz = "";
                  float samples = 16, blur = 0, width = 1, bias = -1)
{
    illuminate(from) {
        vector Lw = vtransform("world", L);
        float x = xcomp(Lw), y = ycomp(Lw), z = zcomp(Lw);
        float ax = abs(x), ay = abs(y), az = abs(z);
        float inshadow = 0;
        /* Each point runs the one lookup of its face (the others are masked off). */
        if (ax >= ay && ax >= az) {
            if (x > 0)
                inshadow = shadowpoint_fraction(sfpx, Ps, samples, blur, width, bias);
            else
                inshadow = shadowpoint_fraction(sfnx, Ps, samples, blur, width, bias);
        } else if (ay >= az) {
            if (y > 0)
                inshadow = shadowpoint_fraction(sfpy, Ps, samples, blur, width, bias);
            else
                inshadow = shadowpoint_fraction(sfny, Ps, samples, blur, width, bias);
        } else {
            if (z > 0)
                inshadow = shadowpoint_fraction(sfpz, Ps, samples, blur, width, bias);
            else
                inshadow = shadowpoint_fraction(sfnz, Ps, samples, blur, width, bias);
        }
        Cl = (1 - inshadow) * intensity * lightcolor / (L . L);
    }
}
