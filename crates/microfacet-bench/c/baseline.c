/* Textbook C implementations of GGX and Beckmann, as a renderer would write them
 * (pbrt-v4 / Heitz 2018 style), for the benchmark baseline. Not part of the library. */
#include <math.h>

static const double PI = 3.14159265358979323846;

double c_ggx_d(double u, double alpha) {
    if (u <= 0.0) return 0.0;
    double a2 = alpha * alpha;
    double t = 1.0 + u * u * (a2 - 1.0);
    return a2 / (PI * t * t);
}

double c_ggx_lambda(double u, double alpha) {
    double u2 = u * u;
    double tan2 = (1.0 - u2) / u2;
    return 0.5 * (-1.0 + sqrt(1.0 + alpha * alpha * tan2));
}

double c_beckmann_d(double u, double alpha) {
    if (u <= 0.0) return 0.0;
    double u2 = u * u;
    double tan2 = (1.0 - u2) / u2;
    double a2 = alpha * alpha;
    return exp(-tan2 / a2) / (PI * a2 * u2 * u2);
}

double c_beckmann_lambda(double u, double alpha) {
    double a = u / (alpha * sqrt(1.0 - u * u));
    return 0.5 * (erf(a) - 1.0) + exp(-a * a) / (2.0 * a * sqrt(PI));
}

/* Heitz 2018, "Sampling the GGX Distribution of Visible Normals". */
void c_ggx_vndf(double vx, double vy, double vz, double ax, double ay, double u1, double u2,
                double *out) {
    double hx = ax * vx, hy = ay * vy, hz = vz;
    double l = sqrt(hx * hx + hy * hy + hz * hz);
    hx /= l; hy /= l; hz /= l;
    double lensq = hx * hx + hy * hy;
    double t1x, t1y, t1z;
    if (lensq > 0.0) {
        double inv = 1.0 / sqrt(lensq);
        t1x = -hy * inv; t1y = hx * inv; t1z = 0.0;
    } else {
        t1x = 1.0; t1y = 0.0; t1z = 0.0;
    }
    double t2x = hy * t1z - hz * t1y, t2y = hz * t1x - hx * t1z, t2z = hx * t1y - hy * t1x;
    double r = sqrt(u1);
    double phi = 2.0 * PI * u2;
    double p1 = r * cos(phi), p2 = r * sin(phi);
    double s = 0.5 * (1.0 + hz);
    p2 = (1.0 - s) * sqrt(1.0 - p1 * p1) + s * p2;
    double p3 = sqrt(fmax(0.0, 1.0 - p1 * p1 - p2 * p2));
    double nx = p1 * t1x + p2 * t2x + p3 * hx;
    double ny = p1 * t1y + p2 * t2y + p3 * hy;
    double nz = p1 * t1z + p2 * t2z + p3 * hz;
    double mx = ax * nx, my = ay * ny, mz = fmax(0.0, nz);
    double m = sqrt(mx * mx + my * my + mz * mz);
    out[0] = mx / m; out[1] = my / m; out[2] = mz / m;
}

/* The same in single precision. */
float c_ggx_d_f(float u, float alpha) {
    if (u <= 0.0f) return 0.0f;
    float a2 = alpha * alpha;
    float t = 1.0f + u * u * (a2 - 1.0f);
    return a2 / ((float)PI * t * t);
}

float c_ggx_lambda_f(float u, float alpha) {
    float u2 = u * u;
    float tan2 = (1.0f - u2) / u2;
    return 0.5f * (-1.0f + sqrtf(1.0f + alpha * alpha * tan2));
}

float c_beckmann_d_f(float u, float alpha) {
    if (u <= 0.0f) return 0.0f;
    float u2 = u * u;
    float tan2 = (1.0f - u2) / u2;
    float a2 = alpha * alpha;
    return expf(-tan2 / a2) / ((float)PI * a2 * u2 * u2);
}

float c_beckmann_lambda_f(float u, float alpha) {
    float a = u / (alpha * sqrtf(1.0f - u * u));
    return 0.5f * (erff(a) - 1.0f) + expf(-a * a) / (2.0f * a * sqrtf((float)PI));
}
