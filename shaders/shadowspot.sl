/* shadowspot: spotlight whose light is stopped by a shadow map (RISpec §15.7.3 shadow()),
   filtered over samples percentage-closer samples, widened by blur (a fraction of the map) and
   width (times the shaded point's footprint); bias < 0 leaves the depth offset to the
   renderer. Without a map (shadowname "") it is spotlight. */
light shadowspot(float intensity = 1; color lightcolor = 1;
                 point from = point "shader" (0, 0, 0); point to = point "shader" (0, 0, 1);
                 float coneangle = radians(30), conedeltaangle = radians(5);
                 float beamdistribution = 2;
                 string shadowname = ""; float samples = 16, blur = 0, width = 1, bias = -1)
{
    vector axis = normalize(to - from);
    illuminate(from, axis, coneangle) {
        float cosangle = (L . axis) / length(L);
        float attenuation = pow(cosangle, beamdistribution) / (L . L);
        attenuation *= smoothstep(cos(coneangle), cos(coneangle - conedeltaangle), cosangle);
        if (shadowname != "")
            attenuation *= 1 - shadow(shadowname, Ps, "samples", samples, "blur", blur,
                                      "width", width, "bias", bias);
        Cl = attenuation * intensity * lightcolor;
    }
}
