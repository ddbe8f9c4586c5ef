//! The textures of `texture ...` commands: piglit's generated images
//! (rgbw quadrants, checkerboards, mipmap trees, shadow ramps, array
//! layers) made with the GL calls piglit's utilities make, on the unit
//! the command names, with the sampler state piglit sets.

use super::super::command::TextureCommand;
use super::super::gl_api::GlApi;
use super::super::images;
use super::Runner;
use gl::enums::*;

impl<G: GlApi> Runner<'_, G> {
    fn new_texture(&mut self, unit: u32, target: u32) {
        self.gl.active_texture(GL_TEXTURE0 + unit);
        let tex = self.gl.gen_texture();
        self.gl.bind_texture(target, tex);
    }

    fn params(&mut self, target: u32, params: &[(u32, u32)]) {
        for &(pname, value) in params {
            self.gl.tex_parameter_i(target, pname, value as i32);
        }
    }

    /// Makes the texture a `texture ...` command asks for.
    /// Enables fixed-function texturing of `target` as piglit's
    /// `shader_runner` does after making a texture, on compatibility
    /// contexts only (core ones have no such capability and would raise
    /// GL_INVALID_ENUM).
    fn enable_fixed_texture(&mut self, target: u32) {
        if !self.core {
            self.gl.enable(target);
        }
    }

    pub(super) fn texture(&mut self, t: &TextureCommand) {
        let nearest = [
            (GL_TEXTURE_MAG_FILTER, GL_NEAREST),
            (GL_TEXTURE_MIN_FILTER, GL_NEAREST),
        ];
        let rgba = GL_RGBA as i32;
        match *t {
            TextureCommand::Rgbw2d {
                unit,
                width,
                height,
            } => {
                self.new_texture(unit, GL_TEXTURE_2D);
                self.params(
                    GL_TEXTURE_2D,
                    &[
                        (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE),
                        (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE),
                    ],
                );
                self.params(GL_TEXTURE_2D, &nearest);
                let img = images::rgbw(width, height);
                self.gl.tex_image_2d(
                    GL_TEXTURE_2D,
                    0,
                    rgba,
                    width as i32,
                    height as i32,
                    0,
                    GL_RGBA,
                    GL_FLOAT,
                    &img,
                );
                self.enable_fixed_texture(GL_TEXTURE_2D);
            }
            TextureCommand::Rgbw1d { unit } => {
                self.new_texture(unit, GL_TEXTURE_1D);
                self.params(
                    GL_TEXTURE_1D,
                    &[
                        (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE),
                        (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE),
                    ],
                );
                self.params(GL_TEXTURE_1D, &nearest);
                let img = images::rgbw_1d();
                self.gl
                    .tex_image_1d(GL_TEXTURE_1D, 0, rgba, 4, 0, GL_RGBA, GL_FLOAT, &img);
            }
            TextureCommand::Rgbw3d { unit } => {
                self.new_texture(unit, GL_TEXTURE_3D);
                self.params(
                    GL_TEXTURE_3D,
                    &[
                        (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE),
                        (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE),
                        (GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE),
                    ],
                );
                self.params(GL_TEXTURE_3D, &nearest);
                let img = images::rgbw_3d();
                self.gl
                    .tex_image_3d(GL_TEXTURE_3D, 0, rgba, 2, 2, 2, 0, GL_RGBA, GL_FLOAT, &img);
            }
            TextureCommand::Miptree { unit } => {
                self.new_texture(unit, GL_TEXTURE_2D);
                self.params(
                    GL_TEXTURE_2D,
                    &[
                        (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE),
                        (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE),
                        (GL_TEXTURE_MAG_FILTER, GL_NEAREST),
                        (GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST),
                    ],
                );
                for (level, (size, img)) in images::miptree().into_iter().enumerate() {
                    self.gl.tex_image_2d(
                        GL_TEXTURE_2D,
                        level as i32,
                        rgba,
                        size as i32,
                        size as i32,
                        0,
                        GL_RGBA,
                        GL_FLOAT,
                        &img,
                    );
                }
                self.enable_fixed_texture(GL_TEXTURE_2D);
            }
            TextureCommand::Checkerboard {
                unit,
                level,
                width,
                height,
                black,
                white,
            } => {
                let img = images::checkerboard(width, height, black, white);
                self.quads_texture(unit, level, width, height, &img);
            }
            TextureCommand::Quads {
                unit,
                level,
                width,
                height,
                square,
                colors,
            } => {
                let img = images::quads(width, height, square, colors);
                self.quads_texture(unit, level, width, height, &img);
            }
            TextureCommand::Shadow {
                unit,
                target,
                width,
                height,
            } => {
                self.new_texture(unit, target);
                self.params(
                    target,
                    &[
                        (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE),
                        (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE),
                    ],
                );
                self.params(target, &nearest);
                let img = images::depth_gradient(width, height);
                let depth = GL_DEPTH_COMPONENT as i32;
                if target == GL_TEXTURE_1D {
                    self.gl.tex_image_1d(
                        target,
                        0,
                        depth,
                        width as i32,
                        0,
                        GL_DEPTH_COMPONENT,
                        GL_FLOAT,
                        &img,
                    );
                } else {
                    self.gl.tex_image_2d(
                        target,
                        0,
                        depth,
                        width as i32,
                        height as i32,
                        0,
                        GL_DEPTH_COMPONENT,
                        GL_FLOAT,
                        &img,
                    );
                }
                self.params(
                    target,
                    &[
                        (GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE),
                        (GL_TEXTURE_COMPARE_FUNC, GL_GREATER),
                    ],
                );
                if target == GL_TEXTURE_2D {
                    self.enable_fixed_texture(GL_TEXTURE_2D);
                }
            }
            TextureCommand::Array {
                unit,
                target,
                width,
                height,
                layers,
                junk,
            } => {
                self.new_texture(unit, target);
                let img = if junk {
                    // Undefined contents: zeros serve.
                    vec![0.0; (width * height * layers * 4) as usize]
                } else {
                    self.params(
                        target,
                        &[
                            (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE),
                            (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE),
                        ],
                    );
                    self.params(target, &nearest);
                    images::array_layers(width, height, layers)
                };
                self.array_texture(target, GL_RGBA, GL_RGBA, width, height, layers, &img);
            }
            TextureCommand::ShadowArray {
                unit,
                target,
                width,
                height,
                layers,
            } => {
                self.new_texture(unit, target);
                self.params(
                    target,
                    &[
                        (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE),
                        (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE),
                    ],
                );
                self.params(target, &nearest);
                let img = images::depth_gradient(width, height * layers);
                let depth = GL_DEPTH_COMPONENT;
                self.array_texture(target, depth, depth, width, height, layers, &img);
                self.params(
                    target,
                    &[
                        (GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE),
                        (GL_TEXTURE_COMPARE_FUNC, GL_GREATER),
                    ],
                );
            }
        }
    }

    /// A 1D or 2D array texture (`texture rgbw/junk ...Array`,
    /// `texture shadow...Array`): `layers` layers of `pixels` (RGBA or
    /// depth) through glTexImage2D (1D arrays: a row per layer) or
    /// glTexImage3D.
    #[allow(clippy::too_many_arguments)]
    fn array_texture(
        &mut self,
        target: u32,
        internal: u32,
        format: u32,
        width: u32,
        height: u32,
        layers: u32,
        pixels: &[f32],
    ) {
        if target == GL_TEXTURE_1D_ARRAY {
            self.gl.tex_image_2d(
                target,
                0,
                internal as i32,
                width as i32,
                layers as i32,
                0,
                format,
                GL_FLOAT,
                pixels,
            );
        } else {
            self.gl.tex_image_3d(
                target,
                0,
                internal as i32,
                width as i32,
                height as i32,
                layers as i32,
                0,
                format,
                GL_FLOAT,
                pixels,
            );
        }
    }

    /// `piglit_quads_texture` with a new texture: nearest filtering,
    /// clamp-to-border wrapping with a red border.
    fn quads_texture(&mut self, unit: u32, level: i32, width: u32, height: u32, img: &[f32]) {
        self.new_texture(unit, GL_TEXTURE_2D);
        self.params(
            GL_TEXTURE_2D,
            &[
                (GL_TEXTURE_MIN_FILTER, GL_NEAREST),
                (GL_TEXTURE_MAG_FILTER, GL_NEAREST),
                (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER),
                (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER),
            ],
        );
        self.gl.tex_parameter_fv(
            GL_TEXTURE_2D,
            GL_TEXTURE_BORDER_COLOR,
            &[1.0, 0.0, 0.0, 1.0],
        );
        self.gl.tex_image_2d(
            GL_TEXTURE_2D,
            level,
            GL_RGBA as i32,
            width as i32,
            height as i32,
            0,
            GL_RGBA,
            GL_FLOAT,
            img,
        );
        self.enable_fixed_texture(GL_TEXTURE_2D);
    }
}
