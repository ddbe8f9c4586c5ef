varying vec4 v[20];
void main()
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 20; i++)
        sum += v[i];
    gl_FragColor = sum;
}
