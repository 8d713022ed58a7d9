package ray.spark;

import java.io.File;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.apache.spark.SparkConf;
import picocli.CommandLine.Option;

/** Where a job runs: {@code --master} and {@code --conf}, for the render, the study and grade (a picocli mixin). */
final class ClusterOptions {

    @Option(names = "--master", paramLabel = "URL", description = "the Spark master: local[*] (default), local[N], spark://host:7077, yarn, k8s://...")
    String master;

    @Option(names = "--conf", paramLabel = "KEY=VALUE", description = "a Spark setting (repeatable), e.g. --conf spark.ui.enabled=false")
    List<String> conf = new ArrayList<>();

    /** What is wrong with these options, or null. */
    String problem() {
        for (String c : conf) {
            if (c.indexOf('=') <= 0) {
                return "--conf takes KEY=VALUE, got '" + c + "'";
            }
        }
        return null;
    }

    /**
     * Spark's settings: spark.* system properties first (what spark-submit passes), then --master (default
     * local[*]) and --conf; {@code cpusPerTask} above 1 sets spark.task.cpus unless given. On a cluster,
     * the jars this program runs from are listed in spark.jars so the executors load its classes from the
     * same jars.
     */
    SparkConf sparkConf(int cpusPerTask) {
        SparkConf c = new SparkConf().setAppName("raytracer-spark");
        if (master != null) {
            c.setMaster(master);
        } else if (!c.contains("spark.master")) {
            c.setMaster("local[*]");
        }
        for (String kv : conf) {
            int eq = kv.indexOf('=');
            c.set(kv.substring(0, eq), kv.substring(eq + 1));
        }
        if (cpusPerTask > 1 && !c.contains("spark.task.cpus")) {
            c.set("spark.task.cpus", Integer.toString(cpusPerTask));
        }
        if (!c.get("spark.master").startsWith("local")) {
            if (!c.contains("spark.jars")) {
                c.set("spark.jars", String.join(",", ownJars()));
            }
            // Spark's module options for executors include ones newer JDKs know (--sun-misc-unsafe-memory-access):
            // a Java 17 executor refuses to start on them unless told to ignore what it does not know
            if (!c.contains("spark.executor.defaultJavaOptions")) {
                c.set("spark.executor.defaultJavaOptions", "-XX:+IgnoreUnrecognizedVMOptions");
            }
        }
        return c;
    }

    /** The jars of the ray tracer and the libraries it needs that Spark does not bring (not Spark's own). */
    static List<String> ownJars() {
        Set<String> jars = new LinkedHashSet<>();
        for (Class<?> c : new Class<?>[] {SparkMain.class, ray.Scene.class, javax.vecmath.Vector3d.class, picocli.CommandLine.class,
                de.javagl.obj.Obj.class}) {
            java.security.CodeSource src = c.getProtectionDomain().getCodeSource();
            if (src != null && src.getLocation() != null && src.getLocation().getPath().endsWith(".jar")) {
                jars.add(new File(src.getLocation().getPath()).getAbsolutePath());
            }
        }
        return new ArrayList<>(jars);
    }
}
