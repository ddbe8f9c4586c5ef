import numpy as np
import pytest

import shaderbox

# A pass-through vertex shader and a flat-colour fragment shader.
VS = """
attribute vec2 pos;
void main() { gl_Position = vec4(pos, 0.0, 1.0); }
"""
FS = """
uniform vec4 color;
void main() { gl_FragColor = color; }
"""
# One triangle covering the whole viewport (and more).
BIG_TRIANGLE = np.array([[-1, -1], [3, -1], [-1, 3]], dtype=np.float32)


@pytest.fixture
def ctx():
    return shaderbox.Context(32, 24, threads=1)
