package ray.light;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Scene;

/**
 * A point light that shines into a cone (Warn 1983): at angle t from the cone's axis the light is
 * {@code I max(0, cos t)^exponent / r^2}, and nothing where t exceeds {@code cutoffAngle}. With
 * {@code cutoffAngle 180} and {@code exponent 0} it is a {@link PointLight}, to the last bit.
 *
 * <pre>
 * Light SpotLight
 * Vector3d position [0 4 0]
 * Vector3d direction [0 -1 0]    # axis of the cone, any length but 0 (default [0 0 -1])
 * Vector3d intensity [20 20 20]  # I on the axis (default [1 1 1])
 * double cutoffAngle 25          # half-angle of the cone in degrees, (0, 180] (default 30)
 * double exponent 8              # falloff inside the cone, >= 0 (default 1)
 * </pre>
 */
public class SpotLight extends PointLight {

    public Vector3d direction = new Vector3d(0, 0, -1);
    public double cutoffAngle = 30;
    public double exponent = 1;

    /** Unit axis and the cosine of the cut-off (-infinity for 180 degrees: nothing is cut off). */
    private double ax, ay, az = -1;
    private double cosCutoff = Math.cos(Math.toRadians(30));

    @Override
    public void init() {
        super.init();
        double len = Math.sqrt(direction.x * direction.x + direction.y * direction.y + direction.z * direction.z);
        if (!(len > 0) || len == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("spot light direction must be a finite vector of non-zero length, got "
                    + direction);
        }
        if (!(cutoffAngle > 0 && cutoffAngle <= 180)) {
            throw new IllegalArgumentException("cutoffAngle must be in (0, 180] degrees, got " + cutoffAngle);
        }
        if (!(exponent >= 0) || exponent == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("exponent must be a finite number >= 0, got " + exponent);
        }
        ax = direction.x / len;
        ay = direction.y / len;
        az = direction.z / len;
        // at 180 degrees every direction is inside, even one whose rounded cosine is below -1
        cosCutoff = cutoffAngle == 180 ? Double.NEGATIVE_INFINITY : Math.cos(Math.toRadians(cutoffAngle));
    }

    @Override
    public boolean sample(IntersectionRecord record, Scene scene, int index, LightSample out) {
        if (!super.sample(record, scene, index, out)) {
            return false;
        }
        // cos t between the axis and the line from the light to the point (out.direction points back)
        Vector3d l = out.direction;
        double cosT = -(ax * l.x + ay * l.y + az * l.z);
        if (cosT < cosCutoff) {
            return false;
        }
        // pow(x, 0) is exactly 1 for every x: exponent 0 leaves the point light's numbers untouched
        double f = Math.pow(Math.max(0, cosT), exponent);
        if (!(f > 0)) {
            return false;
        }
        out.intensity.x *= f;
        out.intensity.y *= f;
        out.intensity.z *= f;
        return true;
    }

    @Override
    public String toString() {
        return "SpotLight[position " + position + ", direction " + direction + ", intensity " + intensity
                + ", cutoffAngle " + cutoffAngle + ", exponent " + exponent + "]";
    }
}
