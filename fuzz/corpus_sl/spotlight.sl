/* spotlight: a point light restricted to a cone around the direction from `from` to `to`,
   softened over conedeltaangle at its edge and concentrated towards its axis by
   beamdistribution. */
light spotlight(float intensity = 1; color lightcolor = 1;
                point from = point "shader" (0, 0, 0); point to = point "shader" (0, 0, 1);
                float coneangle = radians(30), conedeltaangle = radians(5);
                float beamdistribution = 2)
{
    vector axis = normalize(to - from);
    illuminate(from, axis, coneangle) {
        float cosangle = (L . axis) / length(L);
        float attenuation = pow(cosangle, beamdistribution) / (L . L);
        attenuation *= smoothstep(cos(coneangle), cos(coneangle - conedeltaangle), cosangle);
        Cl = attenuation * intensity * lightcolor;
    }
}
