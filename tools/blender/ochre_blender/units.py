"""Unit and convention conversions between Blender (Cycles 3.4) and ochre.

Pure functions on numbers and sequences: no bpy import, so they can be tested with plain python3.

Conventions (measured against Cycles 3.4 on a white Lambertian plane, direct light only):

- Colours: Blender's scene-linear colours are linear Rec.709. An ochre light or emission spectrum written
  as ``[r, g, b]`` is an illuminant whose colour in ochre's (linear Rec.709) EXR is that RGB, so a
  Blender colour times a strength becomes an ochre ``[r, g, b]`` directly.
- Point light of power P (W): radiant intensity I = P / (4 pi) per steradian in every direction.
- Spot light of power P: the intensity on its axis is that of a point light of the same power, P / (4 pi);
  the cone does not concentrate the power.
- Area light of power P and area A: radiance L = P / (4 A), one-sided, Lambertian.
- Sun of strength S (W/m^2): irradiance S on a surface facing it.
- World colour C with strength s: radiance C s from every direction.
- Blender is z-up, ochre y-up: a Blender point (x, y, z) is the ochre point (x, z, -y).
"""
import math
import struct

# Blender world (z up) -> ochre world (y up): (x, y, z) -> (x, z, -y).
Z_UP_TO_Y_UP = ((1.0, 0.0, 0.0, 0.0),
                (0.0, 0.0, 1.0, 0.0),
                (0.0, -1.0, 0.0, 0.0),
                (0.0, 0.0, 0.0, 1.0))


def matmul4(a, b):
    """Product of two 4x4 matrices given as sequences of rows."""
    return tuple(tuple(sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)) for i in range(4))


def to_ochre_matrix(m):
    """A Blender world matrix (4x4 rows) as an ochre transform: 16 numbers, row-major, y up."""
    rows = matmul4(Z_UP_TO_Y_UP, [[float(x) for x in row] for row in m])
    return [float(x) for row in rows for x in row]


def shortest_float32(x):
    """The shortest decimal that reads back as the same single-precision number as x (Blender stores
    locations and colours in single precision: 1.3 instead of 1.2999999523162842)."""
    x = float(x)
    single = struct.unpack('<f', struct.pack('<f', x))[0] if math.isfinite(x) else x
    if single != x:  # not a single-precision value: keep it as it is
        return x
    for digits in range(6, 10):
        shorter = float(f'{x:.{digits}g}')
        if struct.unpack('<f', struct.pack('<f', shorter))[0] == x:
            return shorter
    return x


def to_ochre_point(p):
    return [shortest_float32(p[0]), shortest_float32(p[2]), -shortest_float32(p[1])]


def to_blender_point(p):
    """The inverse of to_ochre_point: an ochre point or direction (y up) in Blender's z-up world."""
    return [float(p[0]), -float(p[2]), float(p[1])]


def to_ochre_direction(d):
    return to_ochre_point(d)


def point_intensity(power_w):
    """Radiant intensity (W/sr) of a Blender point light of power_w watts."""
    return power_w / (4.0 * math.pi)


def spot_intensity(power_w):
    """Radiant intensity on the axis of a Blender spot light of power_w watts."""
    return power_w / (4.0 * math.pi)


def area_radiance(power_w, area):
    """Radiance of a Blender area light of power_w watts and the given area (m^2)."""
    if area <= 0.0:
        raise ValueError('an area light needs a positive area')
    return power_w / (4.0 * area)


def area_of_light(shape, size, size_y):
    """Area of a Blender area light: SQUARE, RECTANGLE, DISK or ELLIPSE with its size(s)."""
    if shape == 'SQUARE':
        return size * size
    if shape == 'RECTANGLE':
        return size * size_y
    if shape == 'DISK':
        return math.pi * size * size / 4.0
    if shape == 'ELLIPSE':
        return math.pi * size * size_y / 4.0
    raise ValueError(f'unknown area light shape {shape!r}')


def sun_irradiance(strength):
    """Irradiance (W/m^2) on a surface facing a Blender sun of the given strength."""
    return strength


def spot_cone(spot_size, spot_blend):
    """(cone_angle, falloff_start) in degrees from Blender's spot_size (full angle, radians) and spot_blend.

    Cycles fades a spot in with a smoothstep in the cosine of the angle from the axis, from cos(spot_size / 2)
    to cos(spot_size / 2) + (1 - cos(spot_size / 2)) spot_blend; ochre's "smoothstep" falloff is the same
    smoothstep from cos(cone_angle) to cos(falloff_start).
    """
    half = spot_size / 2.0
    cos_cone = math.cos(half)
    cos_start = min(1.0, cos_cone + (1.0 - cos_cone) * spot_blend)
    cone = math.degrees(half)
    start = math.degrees(math.acos(cos_start))
    # ochre wants 0 < falloff_start <= cone_angle: rounding may overshoot by an ulp (spot_blend 0), and
    # spot_blend 1 (the fade reaching the axis) is a falloff from a thousandth of a degree.
    return cone, min(max(start, min(1e-3, cone)), cone)


def scaled_colour(colour, scale):
    """An ochre [r, g, b] spectrum: a Blender colour (3 or 4 components) times a scale."""
    return [float(colour[i]) * scale for i in range(3)]


def sensor_fit_axis(sensor_fit, width, height):
    """The film axis ('x' or 'y') Blender measures the camera's sensor (and field of view) across."""
    if sensor_fit == 'HORIZONTAL':
        return 'x'
    if sensor_fit == 'VERTICAL':
        return 'y'
    if sensor_fit == 'AUTO':
        return 'x' if width >= height else 'y'
    raise ValueError(f'unknown sensor fit {sensor_fit!r}')


def perspective_fov(lens_mm, sensor_width, sensor_height, sensor_fit, width, height):
    """(fov in degrees, ochre fov_axis) of a Blender perspective camera.

    AUTO uses the sensor width across the larger image axis, HORIZONTAL the sensor width across the width,
    VERTICAL the sensor height across the height (Blender's BKE_camera_sensor_size).
    """
    axis = sensor_fit_axis(sensor_fit, width, height)
    sensor = sensor_height if sensor_fit == 'VERTICAL' else sensor_width
    return math.degrees(2.0 * math.atan(sensor / (2.0 * lens_mm))), axis


def orthographic_size(ortho_scale, sensor_fit, width, height):
    """ochre's orthographic `size` (extent of the shorter film axis) from Blender's ortho_scale."""
    axis = sensor_fit_axis(sensor_fit, width, height)
    if axis == 'x':
        extent_x, extent_y = ortho_scale, ortho_scale * height / width
    else:
        extent_x, extent_y = ortho_scale * width / height, ortho_scale
    return min(extent_x, extent_y)


def resolution(res_x, res_y, percentage):
    """Film resolution in pixels as Blender computes it with the resolution percentage."""
    return [max(1, int(res_x * percentage / 100)), max(1, int(res_y * percentage / 100))]


def ggx_alpha(roughness):
    """ochre's GGX alpha from Blender's (perceptual) roughness: alpha = roughness^2."""
    r = min(max(float(roughness), 0.0), 1.0)
    return r * r


def environment_rotation(mapping_z_radians):
    """ochre environment `rotation` (degrees) for a Blender Environment Texture whose vector is rotated
    about z by mapping_z_radians (a Mapping node of type POINT; 0 without one).

    Blender's map looks along +x at its centre column and turns clockwise (seen from above) with u; ochre's
    looks along -z (Blender +y) at its centre column: ochre's unrotated map is Blender's turned by 90 degrees.
    """
    r = -math.degrees(mapping_z_radians) - 90.0
    r = math.fmod(r, 360.0)
    return r + 360.0 if r < -180.0 else r


def srgb_encode(c):
    """Linear value in [0, 1] -> sRGB-encoded value in [0, 1]."""
    c = min(max(float(c), 0.0), 1.0)
    return 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1.0 / 2.4) - 0.055
