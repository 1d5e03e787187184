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

/* Beckmann visible normals as pbrt-v3 samples them (Heitz & d'Eon 2014, with Jakob's
 * numerically robust inversion in the erf domain: a fitted initial guess, then Newton steps
 * with bisection to |CDF error| < 1e-5; the inverse error function is Giles' single-precision
 * polynomial, as in pbrt-v3). Written for the baseline; slope sign conventions as in pbrt
 * (its x̃ is the negative of ours). */
static double c_erfinv(double x) {
    double w, p;
    if (x < -0.99999) x = -0.99999;
    if (x > 0.99999) x = 0.99999;
    w = -log((1.0 - x) * (1.0 + x));
    if (w < 5.0) {
        w = w - 2.5;
        p = 2.81022636e-08;
        p = 3.43273939e-07 + p * w;
        p = -3.5233877e-06 + p * w;
        p = -4.39150654e-06 + p * w;
        p = 0.00021858087 + p * w;
        p = -0.00125372503 + p * w;
        p = -0.00417768164 + p * w;
        p = 0.246640727 + p * w;
        p = 1.50140941 + p * w;
    } else {
        w = sqrt(w) - 3.0;
        p = -0.000200214257;
        p = 0.000100950558 + p * w;
        p = 0.00134934322 + p * w;
        p = -0.00367342844 + p * w;
        p = 0.00573950773 + p * w;
        p = -0.0076224613 + p * w;
        p = 0.00943887047 + p * w;
        p = 1.00167406 + p * w;
        p = 2.83297682 + p * w;
    }
    return p * x;
}

static void c_beckmann_sample11(double cos_i, double u1, double u2, double *sx, double *sy) {
    if (cos_i > 0.9999) {
        double r = sqrt(-log(1.0 - u1));
        double phi = 2.0 * PI * u2;
        *sx = r * cos(phi);
        *sy = r * sin(phi);
        return;
    }
    double sin_i = sqrt(fmax(0.0, 1.0 - cos_i * cos_i));
    double tan_i = sin_i / cos_i;
    double cot_i = 1.0 / tan_i;
    double a = -1.0, c = erf(cot_i);
    double x = fmax(u1, 1e-6);
    double theta = acos(cos_i);
    double fit = 1.0 + theta * (-0.876 + theta * (0.4265 - 0.0594 * theta));
    double b = c - (1.0 + c) * pow(1.0 - x, fit);
    double sqrt_pi_inv = 1.0 / sqrt(PI);
    double norm = 1.0 / (1.0 + c + sqrt_pi_inv * tan_i * exp(-cot_i * cot_i));
    for (int it = 1; it < 10; ++it) {
        if (!(b >= a && b <= c)) b = 0.5 * (a + c);
        double inv = c_erfinv(b);
        double value = norm * (1.0 + b + sqrt_pi_inv * tan_i * exp(-inv * inv)) - x;
        double deriv = norm * (1.0 - inv * tan_i);
        if (fabs(value) < 1e-5) break;
        if (value > 0.0) c = b; else a = b;
        b -= value / deriv;
    }
    *sx = c_erfinv(b);
    *sy = c_erfinv(2.0 * fmax(u2, 1e-6) - 1.0);
}

void c_beckmann_vndf(double vx, double vy, double vz, double ax, double ay, double u1,
                     double u2, double *out) {
    double sx = ax * vx, sy = ay * vy, sz = vz;
    double l = sqrt(sx * sx + sy * sy + sz * sz);
    sx /= l; sy /= l; sz /= l;
    double sin_t = sqrt(fmax(0.0, 1.0 - sz * sz));
    double cos_p = sin_t == 0.0 ? 1.0 : fmin(fmax(sx / sin_t, -1.0), 1.0);
    double sin_p = sin_t == 0.0 ? 0.0 : fmin(fmax(sy / sin_t, -1.0), 1.0);
    double px, py;
    c_beckmann_sample11(sz, u1, u2, &px, &py);
    double tmp = cos_p * px - sin_p * py;
    py = sin_p * px + cos_p * py;
    px = tmp;
    px *= ax; py *= ay;
    double m = sqrt(px * px + py * py + 1.0);
    out[0] = -px / m; out[1] = -py / m; out[2] = 1.0 / m;
}
