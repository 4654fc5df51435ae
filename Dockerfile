# Shadowlab in a container, for macOS, Windows and any Linux that is not Debian 12, 13 or 14: the
# same Debian packages ./kit installs, and the kit built once. Inside, the README's two commands
# run as they do on Debian (`./kit demo`, `./kit test`).
#   docker build -t shadowlab .                        # Debian 12 (Mesa 22.3)
#   docker build -t shadowlab:13 --build-arg DEBIAN=13 .   # Debian 13 (Mesa 25.0)
#   docker run --rm -it -v "$PWD/out:/shadowlab/out" shadowlab ./kit demo
# VS Code and Codespaces open the kit in this image (.devcontainer/devcontainer.json); Gradescope
# can use it as a custom autograder image (docs/grading.md, "Gradescope").
ARG DEBIAN=12
FROM debian:${DEBIAN}
ENV DEBIAN_FRONTEND=noninteractive LANG=C.UTF-8
WORKDIR /shadowlab
# The package list first (one layer, reused while ./kit's list is unchanged): ./kit installs
# what it needs when it runs as root.
COPY kit ./kit
RUN ./kit deps && rm -rf /var/lib/apt/lists/*
COPY . .
RUN cmake --preset default >/dev/null && cmake --build build -j "$(nproc)" --target shadowlab
CMD ["./kit", "demo"]
