void main(int x)
{
    gl_FragColor = vec4(1.0);
}
