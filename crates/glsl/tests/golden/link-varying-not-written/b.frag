varying vec3 normal;
varying vec2 uv;
void main() { gl_FragColor = vec4(normal, uv.x); }
