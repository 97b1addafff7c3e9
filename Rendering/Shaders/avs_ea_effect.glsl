//AVS::Effect::Dec
// Emission-absorption (ALGORITHM.md section 2): L += T (1 - exp(-sigma_t dt)) c.
//AVS::Effect::Sample
    L += T * (1.0 - extinction) * here.rgb;
