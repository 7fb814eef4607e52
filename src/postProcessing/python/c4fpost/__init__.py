"""contact4foam post-processing: readers for OpenFOAM ASCII output and the
closed-form solutions the tutorials and tests compare against."""
