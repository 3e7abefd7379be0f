# Two commands do all the set-up on a fresh Debian machine with Python ≥ 3.11:
#   make run    set up, then run the assistant on its built-in default (the simulated apartment)
#   make test   set up, then run the tests
#   make notebook  set up, then start JupyterLab on notebooks/ (127.0.0.1 only, with its token)
VENV ?= .venv
PY := $(VENV)/bin/python
SYSTEM_PACKAGES := libusb-1.0-0 libgomp1 libgl1 libegl1 libglib2.0-0 libx11-6 espeak-ng libportaudio2 sphinxtrain sphinxbase-utils pocketsphinx libfreenect-dev libfreenect-bin chromium
STAMP := $(VENV)/.installed

.PHONY: run test notebook setup warm-up system-packages bench clean

# warm-up trains (or loads) every model the chat uses, with progress, so its first reply is quick
run: setup warm-up
	$(VENV)/bin/assistant chat --world apartment

warm-up: setup
	$(VENV)/bin/assistant warm-up --world apartment

# the tests run on every core (pytest-xdist, one test file per worker at a time); the workers
# share one private model cache, and a model is trained by the first worker that needs it
test: setup
	$(PY) -m pytest -q -n logical --dist loadfile

# JupyterLab on the notebooks, listening on 127.0.0.1 only; it prints the URL with its token
# (as root, e.g. in a container, JupyterLab needs --allow-root).
notebook: setup warm-up
	$(VENV)/bin/jupyter lab --no-browser --ip=127.0.0.1 --ServerApp.root_dir=notebooks \
	  $$( [ "$$(id -u)" = 0 ] && echo --allow-root )

bench: setup
	$(PY) benchmarks/run_all.py

setup: $(STAMP)

# System libraries open3d (libusb, libgomp, GL/EGL for its module), speech output (espeak-ng),
# the microphone and sound output (libportaudio2, for sounddevice), speaker enrolment
# (SphinxTrain's bw and map_adapt, sphinxbase's sphinx_fe, pocketsphinx's mdef converter),
# the Kinect (libfreenect-dev to build the freenect binding; libfreenect-bin for fakenect),
# headless Chromium for the tests that render the 3D scenes (tests/viz/test_browser.py).
system-packages:
	@missing=""; for p in $(SYSTEM_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing system packages:$$missing"; \
	  SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing; \
	fi

$(STAMP): pyproject.toml | system-packages
	python3 -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q -e '.[dev,kinect]' || { echo 'the Kinect binding (freenect) did not build: installing without it'; $(PY) -m pip install -q -e '.[dev]'; }
	touch $(STAMP)

clean:
	rm -rf $(VENV) .pytest_cache
