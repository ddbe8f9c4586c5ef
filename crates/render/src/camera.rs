//! The camera: fits a bounding sphere of the molecule into the view.
//!
//! The molecule is turned about its centre (first about the screen X axis,
//! then Y, then Z, by the given degrees) and looked at down eye-space -z.
//! Orthographic: the view is the bounding sphere's extent plus a 5%
//! margin along the shorter image side; the eye sits 3 sphere radii away
//! (which only matters for fog). Perspective: a 30° vertical field of view
//! (narrower side: 30°), the eye far enough back that the whole bounding
//! sphere (plus 5%) is inside the view cone.

use glsl::math;

/// Projection of the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Projection {
    #[default]
    Orthographic,
    Perspective,
}

/// Vertical (or, for tall images, horizontal) field of view in
/// perspective, degrees.
pub const FIELD_OF_VIEW: f32 = 30.0;
/// Margin around the bounding sphere.
pub const MARGIN: f32 = 1.05;

/// A fitted camera: everything the GL projection and model-view need.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    pub projection: Projection,
    /// Centre of the bounding sphere (object space, Å).
    pub center: [f32; 3],
    /// Radius of the bounding sphere including atom radii.
    pub radius: f32,
    /// Distance from the eye to the centre.
    pub distance: f32,
    pub near: f32,
    pub far: f32,
    /// Half extents of the view: at the near plane (perspective) or of the
    /// box (orthographic).
    pub half_width: f32,
    pub half_height: f32,
    /// Rotation about X, Y, Z in degrees.
    pub rotate: [f32; 3],
}

impl Camera {
    /// Fits spheres (`centre`, `radius`) into a `width` x `height` image.
    pub fn fit(
        spheres: &[([f32; 3], f32)],
        projection: Projection,
        width: u32,
        height: u32,
        rotate: [f32; 3],
    ) -> Camera {
        let mut lo = [f32::INFINITY; 3];
        let mut hi = [f32::NEG_INFINITY; 3];
        for (p, _) in spheres {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let center = if spheres.is_empty() {
            [0.0; 3]
        } else {
            [0, 1, 2].map(|k| 0.5 * lo[k] + 0.5 * hi[k])
        };
        let mut radius: f32 = 0.0;
        for (p, r) in spheres {
            let d = [p[0] - center[0], p[1] - center[1], p[2] - center[2]];
            let len = math::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            radius = radius.max(len + r.max(0.0));
        }
        if !radius.is_finite() || radius <= 0.0 {
            radius = 1.0;
        }
        let fitted = radius * MARGIN;
        let aspect = width.max(1) as f32 / height.max(1) as f32;
        match projection {
            Projection::Orthographic => {
                let (hw, hh) = if aspect >= 1.0 {
                    (fitted * aspect, fitted)
                } else {
                    (fitted, fitted / aspect)
                };
                let distance = 3.0 * radius;
                Camera {
                    projection,
                    center,
                    radius,
                    distance,
                    near: distance - 1.5 * radius,
                    far: distance + 1.5 * radius,
                    half_width: hw,
                    half_height: hh,
                    rotate,
                }
            }
            Projection::Perspective => {
                let tan_half = math::tan(math::radians(FIELD_OF_VIEW * 0.5));
                let (tan_x, tan_y) = if aspect >= 1.0 {
                    (tan_half * aspect, tan_half)
                } else {
                    (tan_half, tan_half / aspect)
                };
                let t = tan_x.min(tan_y);
                // The cone of half-angle atan(t) holds the sphere when
                // distance = R / sin(atan t) = R sqrt(1 + t^2) / t.
                let distance = fitted * math::sqrt(1.0 + t * t) / t;
                let near = (distance - 1.1 * radius).max(distance * 0.01);
                let far = distance + 1.1 * radius;
                Camera {
                    projection,
                    center,
                    radius,
                    distance,
                    near,
                    far,
                    half_width: near * tan_x,
                    half_height: near * tan_y,
                    rotate,
                }
            }
        }
    }

    /// Eye-space depth range |z| the molecule occupies (front, back).
    pub fn depth_span(&self) -> (f32, f32) {
        (self.distance - self.radius, self.distance + self.radius)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ortho_fits_sphere_with_margin() {
        let c = Camera::fit(
            &[([0.0, 0.0, 0.0], 1.0), ([4.0, 0.0, 0.0], 1.0)],
            Projection::Orthographic,
            200,
            100,
            [0.0; 3],
        );
        assert_eq!(c.center, [2.0, 0.0, 0.0]);
        assert_eq!(c.radius, 3.0);
        assert!((c.half_height - 3.15).abs() < 1e-5);
        assert!((c.half_width - 6.3).abs() < 1e-5);
        assert!(c.near < c.distance - c.radius && c.far > c.distance + c.radius);
    }

    #[test]
    fn perspective_cone_holds_sphere() {
        let c = Camera::fit(
            &[([1.0, 2.0, 3.0], 2.0)],
            Projection::Perspective,
            100,
            100,
            [0.0; 3],
        );
        // Half-angle 15 degrees: sin = R' / distance.
        let s = c.radius * MARGIN / c.distance;
        assert!((s - math::sin(math::radians(15.0))).abs() < 1e-4, "{s}");
        assert!(c.near > 0.0 && c.near < c.distance - c.radius);
        assert!(c.far > c.distance + c.radius);
    }

    #[test]
    fn degenerate_input_is_defined() {
        let c = Camera::fit(&[], Projection::Perspective, 0, 0, [0.0; 3]);
        assert!(c.distance.is_finite() && c.radius == 1.0);
    }
}
