/*
 * profsubd from plain C99: build a creased cube through the C API, check it, write it as
 * OBJ with OpenSubdiv tags, read it back and compare.
 *
 *   cube_example [OUT.obj]      (default: cube.obj in the current directory)
 *
 * Exit code 0 when every step gives the expected answer.
 */
#include <profsubd.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Prints the failing call with the library's message and returns 1. */
static int report(const char *call, profsubd_status status) {
    fprintf(stderr, "%s failed: %s: %s\n", call, profsubd_status_string((int32_t)status),
            profsubd_last_error_message());
    return 1;
}

/* Copies out the positions the documented way: ask for the size, allocate, fill. */
static double *copy_positions(const profsubd_mesh *mesh, size_t *count) {
    size_t needed = 0;
    profsubd_status st = profsubd_mesh_get_positions(mesh, NULL, 0, &needed);
    double *buf;
    if (st != PROFSUBD_ERROR_BUFFER_TOO_SMALL) {
        report("profsubd_mesh_get_positions (size query)", st);
        return NULL;
    }
    buf = (double *)malloc(needed * sizeof *buf);
    if (buf == NULL) {
        return NULL;
    }
    st = profsubd_mesh_get_positions(mesh, buf, needed, count);
    if (st != PROFSUBD_OK) {
        report("profsubd_mesh_get_positions", st);
        free(buf);
        return NULL;
    }
    return buf;
}

int main(int argc, char **argv) {
    /* A unit cube, faces counter-clockwise seen from outside. */
    static const double positions[8 * 3] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                            0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    static const uint32_t face_sizes[6] = {4, 4, 4, 4, 4, 4};
    static const uint32_t face_indices[24] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                                              1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
    /* The four top edges are semi-sharp creases, vertex 0 an infinitely sharp corner. */
    static const uint32_t crease_vertices[4 * 2] = {4, 5, 5, 6, 6, 7, 7, 4};
    static const float crease_sharpness[4] = {2.0f, 2.0f, 2.0f, 2.0f};
    static const uint32_t corner_vertices[1] = {0};
    static const float corner_sharpness[1] = {10.0f};

    const char *path = argc > 1 ? argv[1] : "cube.obj";
    profsubd_mesh_desc desc;
    profsubd_mesh *cube = NULL, *back = NULL;
    profsubd_mesh_report rep;
    profsubd_options *options = NULL;
    profsubd_status st;
    size_t nv = 0, ne = 0, nf = 0, nc = 0, n1 = 0, n2 = 0;
    double *p1, *p2;
    int same;

    printf("profsubd %s\n", profsubd_version_string());

    memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc; /* lets later library versions extend the struct */
    desc.positions = positions;
    desc.num_vertices = 8;
    desc.face_sizes = face_sizes;
    desc.num_faces = 6;
    desc.face_indices = face_indices;
    desc.num_face_indices = 24;
    desc.crease_vertices = crease_vertices;
    desc.crease_sharpness = crease_sharpness;
    desc.num_creases = 4;
    desc.corner_vertices = corner_vertices;
    desc.corner_sharpness = corner_sharpness;
    desc.num_corners = 1;
    if ((st = profsubd_mesh_new(&desc, &cube)) != PROFSUBD_OK) {
        return report("profsubd_mesh_new", st);
    }

    profsubd_mesh_num_vertices(cube, &nv);
    profsubd_mesh_num_edges(cube, &ne);
    profsubd_mesh_num_faces(cube, &nf);
    profsubd_mesh_num_creases(cube, &nc);
    memset(&rep, 0, sizeof rep);
    rep.struct_size = sizeof rep;
    if ((st = profsubd_mesh_check(cube, &rep)) != PROFSUBD_OK) {
        return report("profsubd_mesh_check", st);
    }
    printf("cube: %zu vertices, %zu edges, %zu faces, %zu creases, Euler characteristic %lld, %s\n", nv, ne, nf,
           nc, (long long)rep.euler_characteristic, rep.is_manifold ? "manifold" : "not manifold");

    /* Options are a handle with setters: new settings never change a struct layout. */
    if ((st = profsubd_options_new(&options)) != PROFSUBD_OK ||
        (st = profsubd_options_set_boundary(options, PROFSUBD_BOUNDARY_EDGE_AND_CORNER)) != PROFSUBD_OK) {
        return report("profsubd_options", st);
    }
    /* A wrong value is an error with a message, never undefined behaviour. */
    st = profsubd_options_set_boundary(options, 42);
    printf("set_boundary(42): %s: %s\n", profsubd_status_string((int32_t)st), profsubd_last_error_message());
    profsubd_options_free(options);

    if ((st = profsubd_mesh_write_obj(cube, path)) != PROFSUBD_OK) {
        return report("profsubd_mesh_write_obj", st);
    }
    if ((st = profsubd_mesh_read_obj(path, &back)) != PROFSUBD_OK) {
        return report("profsubd_mesh_read_obj", st);
    }
    p1 = copy_positions(cube, &n1);
    p2 = copy_positions(back, &n2);
    same = p1 != NULL && p2 != NULL && n1 == n2 && memcmp(p1, p2, n1 * sizeof *p1) == 0;
    printf("wrote %s and read it back: positions %s\n", path, same ? "identical" : "DIFFERENT");
    free(p1);
    free(p2);
    profsubd_mesh_free(back);
    profsubd_mesh_free(cube);

    if (nv != 8 || ne != 12 || nf != 6 || nc != 4 || rep.euler_characteristic != 2 || !rep.is_manifold ||
        st != PROFSUBD_OK || !same) {
        fprintf(stderr, "unexpected result\n");
        return 1;
    }
    return 0;
}
