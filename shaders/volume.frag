// volume.frag: volume ray casting through a 3D texture (fragment stage;
// vertex: volume.vert).
//
// What it does: marches from ray_start along the normalised ray_direction
// in `steps` equal steps of sqrt(3) / steps (the cube's diagonal, so every
// ray crosses the whole volume; at most MAX_STEPS), samples the RGBA 3D
// texture `volume` at each point inside the unit cube (a small epsilon
// outside counts as inside), and composites front to back:
//   result += alpha_acc * alpha_i * color_i
//   result_alpha += alpha_acc * alpha_i
//   alpha_acc *= 1 - alpha_i
// with color_i = texel.rgb and alpha_i = clamp(texel.a * opacity, 0, 1).
// It writes vec4(result + alpha_acc * background, result_alpha).
//
// State it reads: uniform sampler3D volume; uniform int steps (1 to
// MAX_STEPS); uniform float opacity; uniform vec3 background;
// `varying vec3 ray_start, ray_direction`.
//
// Fix of the seed ("Shaders" slides, seed 004, "Shader Code"): the
// slides' loop sets alpha_acc = (1.0 - alpha_i), forgetting the
// transparency accumulated so far; front-to-back compositing multiplies
// (alpha_acc *= 1.0 - alpha_i), as the slides' own sum of products says.
// The slides leave alpha_i and color_i as ?? placeholders; here they come
// from the texture as above.

uniform sampler3D volume;
uniform int steps;
uniform float opacity;
uniform vec3 background;

varying vec3 ray_start;
varying vec3 ray_direction;

const int MAX_STEPS = 256;
const float EPSILON = 0.001;

void main(void)
{
    int n = steps;
    if (n < 1)
        n = 1;
    if (n > MAX_STEPS)
        n = MAX_STEPS;
    vec3 dir_step = normalize(ray_direction) * (1.7320508 / float(n));
    vec3 position = ray_start;
    vec3 low = vec3(-EPSILON);
    vec3 high = vec3(1.0 + EPSILON);

    float alpha_acc = 1.0;
    vec3 result = vec3(0.0);
    float result_alpha = 0.0;
    for (int i = 0; i < MAX_STEPS; i++) {
        if (i >= n)
            break;
        if (all(greaterThan(position, low)) && all(lessThan(position, high))) {
            vec4 texel = texture3D(volume, position);
            float alpha_i = clamp(texel.a * opacity, 0.0, 1.0);
            result += alpha_acc * alpha_i * texel.rgb;
            result_alpha += alpha_acc * alpha_i;
            alpha_acc *= 1.0 - alpha_i;
        }
        position += dir_step;
    }
    gl_FragColor = vec4(result + alpha_acc * background, result_alpha);
}
