package ray.spark;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;
import org.apache.spark.api.java.function.Function;
import scala.runtime.AbstractFunction1;

/**
 * The executor side of a partition for {@code SparkContext.runJob}: each of its tasks (one, as the jobs
 * cut them) through {@code f}, the results as an array of {@code type}, so the driver's result handler gets
 * them as each partition finishes.
 */
final class EachTask<T, R> extends AbstractFunction1<scala.collection.Iterator<T>, R[]> implements Serializable {
    private static final long serialVersionUID = 1L;
    private final Function<T, R> f;
    private final Class<R> type;

    EachTask(Function<T, R> f, Class<R> type) {
        this.f = f;
        this.type = type;
    }

    @Override
    public R[] apply(scala.collection.Iterator<T> it) {
        List<R> out = new ArrayList<>();
        try {
            while (it.hasNext()) {
                out.add(f.call(it.next()));
            }
        } catch (RuntimeException | Error e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
        @SuppressWarnings("unchecked")
        R[] array = (R[]) java.lang.reflect.Array.newInstance(type, out.size());
        return out.toArray(array);
    }

    /** The class tag runJob needs for an array of {@code type}. */
    @SuppressWarnings("unchecked")
    static <R> scala.reflect.ClassTag<R[]> arrayTag(Class<R> type) {
        return scala.reflect.ClassTag$.MODULE$.apply(java.lang.reflect.Array.newInstance(type, 0).getClass());
    }
}
