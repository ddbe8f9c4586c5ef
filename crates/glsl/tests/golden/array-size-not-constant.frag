uniform int n;
void main()
{
    float a[n];
    gl_FragColor = vec4(1.0);
}
