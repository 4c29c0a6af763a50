// The viewer of medialaxis's self-contained page (vtkMedialHTMLWriter). The page holds a
// manifest (<script id="medial-manifest">) and one vtk.js dataset per layer, written by
// VTK's vtkJSONDataSetWriter and read back here by vtkHttpDataSetReader through the
// "html" data access helper: nothing is fetched from the network. This file builds the
// scene (vtk.js actors and mappers) and the controls; window.medialViewer is the page's
// state and a pick() for scripts and the browser test.
import '@kitware/vtk.js/Rendering/OpenGL/Actor';
import '@kitware/vtk.js/Rendering/OpenGL/Camera';
import '@kitware/vtk.js/Rendering/OpenGL/PolyDataMapper';
import '@kitware/vtk.js/Rendering/OpenGL/Renderer';
import '@kitware/vtk.js/Rendering/OpenGL/SphereMapper';
import vtkOpenGLRenderWindow from '@kitware/vtk.js/Rendering/OpenGL/RenderWindow';
import vtkActor from '@kitware/vtk.js/Rendering/Core/Actor';
import vtkCellPicker from '@kitware/vtk.js/Rendering/Core/CellPicker';
import vtkColorTransferFunction from '@kitware/vtk.js/Rendering/Core/ColorTransferFunction';
import vtkMapper from '@kitware/vtk.js/Rendering/Core/Mapper';
import vtkPointPicker from '@kitware/vtk.js/Rendering/Core/PointPicker';
import vtkRenderer from '@kitware/vtk.js/Rendering/Core/Renderer';
import vtkRenderWindow from '@kitware/vtk.js/Rendering/Core/RenderWindow';
import vtkRenderWindowInteractor from '@kitware/vtk.js/Rendering/Core/RenderWindowInteractor';
import vtkSphereMapper from '@kitware/vtk.js/Rendering/Core/SphereMapper';
import vtkInteractorStyleTrackballCamera from '@kitware/vtk.js/Interaction/Style/InteractorStyleTrackballCamera';
import vtkInteractorStyleManipulator from '@kitware/vtk.js/Interaction/Style/InteractorStyleManipulator';
import vtkMouseCameraTrackballPanManipulator from '@kitware/vtk.js/Interaction/Manipulators/MouseCameraTrackballPanManipulator';
import vtkMouseCameraTrackballZoomManipulator from '@kitware/vtk.js/Interaction/Manipulators/MouseCameraTrackballZoomManipulator';
import vtkHttpDataSetReader from '@kitware/vtk.js/IO/Core/HttpDataSetReader';
import DataAccessHelper from '@kitware/vtk.js/IO/Core/DataAccessHelper';
import '@kitware/vtk.js/IO/Core/DataAccessHelper/HtmlDataAccessHelper';
import vtkDataArray from '@kitware/vtk.js/Common/Core/DataArray';
import vtkPoints from '@kitware/vtk.js/Common/Core/Points';
import vtkCellArray from '@kitware/vtk.js/Common/Core/CellArray';
import vtkPolyData from '@kitware/vtk.js/Common/DataModel/PolyData';

import css from './style.css';
import { el, checkbox, slider, fieldset, legendRows, ramp, format } from './ui.js';

// Colours shared with vtkMedialScene's pictures.
const RADIUS_RAMP = [[0, 0, 1], [0, 1, 1], [0, 1, 0], [1, 1, 0], [1, 0, 0]]; // blue (thin) to red (thick)
const TYPES_3D = [['rim', [0.20, 0.45, 0.85]], ['sheet', [0.78, 0.78, 0.75]], ['seam', [0.95, 0.55, 0.10]],
  ['junction', [0.85, 0.10, 0.10]]];
const TYPES_2D = [['end point', [0.1, 0.65, 0.2]], ['regular', [0.15, 0.35, 0.85]], ['junction', [0.85, 0.1, 0.1]]];
const ARCS = [['linear', [0.15, 0.35, 0.85]], ['parabolic', [0.95, 0.55, 0.1]]];
const THIN = [0.85, 0.1, 0.1];
const SURFACE_GREY = [0.80, 0.82, 0.86];
const COPPER = [0.90, 0.62, 0.40];

function fail(error) {
  const box = document.getElementById('medial-error');
  if (box) {
    box.textContent = `The page could not be shown: ${error && error.message ? error.message : error}`;
    box.style.display = 'block';
  }
  document.documentElement.dataset.medialStatus = 'error';
  console.error('medialaxis page:', error);
}

function readManifest() {
  const node = document.getElementById('medial-manifest');
  if (!node) throw new Error('no manifest in this page');
  return JSON.parse(node.textContent);
}

// A layer's dataset, through vtk.js's reader of VTK's export.
async function loadDataset(url) {
  const reader = vtkHttpDataSetReader.newInstance({ fetchGzip: true, dataAccessHelper: DataAccessHelper.get('html') });
  await reader.setUrl(url, { fullpath: true, loadData: true });
  return reader.getOutputData();
}

function rampFunction(lo, hi, stops = RADIUS_RAMP) {
  const ctf = vtkColorTransferFunction.newInstance();
  const span = hi > lo ? hi - lo : 1;
  stops.forEach((rgb, i) => ctf.addRGBPoint(lo + (span * i) / (stops.length - 1), ...rgb));
  return ctf;
}

function categoryFunction(table) {
  const ctf = vtkColorTransferFunction.newInstance();
  table.forEach(([, rgb], code) => ctf.addRGBPoint(code, ...rgb));
  return ctf;
}

function colourBy(mapper, array, ctf, cells = false) {
  mapper.setLookupTable(ctf);
  mapper.setUseLookupTableScalarRange(true);
  mapper.setColorByArrayName(array);
  mapper.setScalarMode(cells ? 4 : 3); // USE_CELL_FIELD_DATA : USE_POINT_FIELD_DATA
  mapper.setColorMode(1); // MAP_SCALARS
  mapper.setScalarVisibility(true);
}

function finiteRange(values) {
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < values.length; ++i) {
    const v = values[i];
    if (Number.isFinite(v)) {
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
  }
  return lo <= hi ? [lo, hi] : [0, 1];
}

// A point subset of `source` (indices `ids`) with copies of the named point arrays.
function pointSubset(source, ids, names) {
  const from = source.getPoints().getData();
  const xyz = new Float32Array(3 * ids.length);
  ids.forEach((id, k) => {
    xyz[3 * k] = from[3 * id];
    xyz[3 * k + 1] = from[3 * id + 1];
    xyz[3 * k + 2] = from[3 * id + 2];
  });
  const subset = vtkPolyData.newInstance();
  subset.setPoints(vtkPoints.newInstance({ values: xyz, numberOfComponents: 3 }));
  names.forEach((name) => {
    const array = source.getPointData().getArrayByName(name);
    if (!array) return;
    const values = array.getData();
    const copy = new values.constructor(ids.length);
    ids.forEach((id, k) => { copy[k] = values[id]; });
    subset.getPointData().addArray(vtkDataArray.newInstance({ name, values: copy }));
  });
  return subset;
}

// Circles (96-gons) of the given centres and radii in the plane of `right` and `up`.
function circles(centres, radii, right, up) {
  const n = 96;
  const xyz = new Float32Array(3 * n * radii.length);
  const cells = new Uint32Array((n + 2) * radii.length);
  let p = 0;
  let c = 0;
  radii.forEach((r, k) => {
    cells[c++] = n + 1;
    const first = p / 3;
    for (let i = 0; i < n; ++i) {
      const a = (2 * Math.PI * i) / n;
      for (let d = 0; d < 3; ++d) xyz[p++] = centres[k][d] + r * (Math.cos(a) * right[d] + Math.sin(a) * up[d]);
      cells[c++] = first + i;
    }
    cells[c++] = first;
  });
  const pd = vtkPolyData.newInstance();
  pd.setPoints(vtkPoints.newInstance({ values: xyz, numberOfComponents: 3 }));
  pd.setLines(vtkCellArray.newInstance({ values: cells }));
  return pd;
}

function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

function actorOf(mapper, rgb) {
  const actor = vtkActor.newInstance();
  actor.setMapper(mapper);
  if (rgb) actor.getProperty().setColor(...rgb);
  return actor;
}

function meshPart(mesh, cells) {
  const part = vtkPolyData.newInstance();
  part.setPoints(mesh.getPoints());
  if (cells === 'polys') part.setPolys(mesh.getPolys());
  else part.setLines(mesh.getLines());
  ['MedialPointType', 'Radius'].forEach((name) => {
    const array = mesh.getPointData().getArrayByName(name);
    if (array) part.getPointData().addArray(array);
  });
  return part;
}

function indicesOfType(types, code) {
  const ids = [];
  for (let i = 0; i < types.length; ++i) if (types[i] === code) ids.push(i);
  return ids;
}

async function main() {
  const style = document.createElement('style');
  style.textContent = css;
  document.head.appendChild(style);
  const manifest = readManifest();
  const layers = manifest.layers || {};
  const planar = !!manifest.planar;

  // Page layout: the controls on the left, the view on the right.
  const panel = el('aside', { id: 'medial-panel' });
  const view = el('main', { id: 'medial-view' });
  view.appendChild(el('div', { id: 'medial-error' }));
  document.body.appendChild(el('div', { id: 'medial-app' }, [panel, view]));
  panel.appendChild(el('h1', { id: 'medial-title' }, manifest.title || 'medialaxis'));
  if (manifest.details) panel.appendChild(el('p', { className: 'details' }, manifest.details));

  const data = {};
  for (const name of Object.keys(layers)) {
    data[name] = await loadDataset(layers[name].url);
  }

  // Rendering: one view, and a second one for the reconstruction through the same camera.
  const renderWindow = vtkRenderWindow.newInstance();
  const renderer = vtkRenderer.newInstance({ background: [1, 1, 1] });
  renderWindow.addRenderer(renderer);
  const glWindow = vtkOpenGLRenderWindow.newInstance();
  renderWindow.addView(glWindow);
  glWindow.setContainer(view);
  const interactor = vtkRenderWindowInteractor.newInstance();
  interactor.setView(glWindow);
  interactor.initialize();
  interactor.bindEvents(view);
  if (planar) {
    const style2d = vtkInteractorStyleManipulator.newInstance();
    style2d.addMouseManipulator(vtkMouseCameraTrackballPanManipulator.newInstance({ button: 1 }));
    style2d.addMouseManipulator(vtkMouseCameraTrackballZoomManipulator.newInstance({ button: 3 }));
    style2d.addMouseManipulator(vtkMouseCameraTrackballZoomManipulator.newInstance({ scrollEnabled: true, dragEnabled: false }));
    interactor.setInteractorStyle(style2d);
  } else {
    interactor.setInteractorStyle(vtkInteractorStyleTrackballCamera.newInstance());
  }
  let pending = false;
  const render = () => {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => {
      pending = false;
      renderWindow.render();
    });
  };
  const resize = () => {
    const { width, height } = view.getBoundingClientRect();
    const scale = window.devicePixelRatio || 1;
    glWindow.setSize(Math.max(1, Math.floor(width * scale)), Math.max(1, Math.floor(height * scale)));
    renderWindow.render();
  };

  const state = { layers: {}, controls: [] };
  const register = (name, actor, extra = {}) => {
    state.layers[name] = { actor, ...extra };
    return actor;
  };
  const pickables = []; // [actor, kind, describe(id, position)]

  // The input surface (3D: translucent, or coloured by thickness; 2D: its outline).
  if (data.surface) {
    const surface = data.surface;
    const mapper = vtkMapper.newInstance({ scalarVisibility: false });
    mapper.setInputData(surface);
    const actor = actorOf(mapper, layers.surface.outline ? [0.1, 0.1, 0.1] : SURFACE_GREY);
    renderer.addActor(register('surface', actor, { points: surface.getNumberOfPoints(), cells: surface.getNumberOfCells() }));
    const box = fieldset(panel, layers.surface.outline ? 'Outline' : 'Surface', 'surface');
    const opacityDefault = layers.surface.outline ? 1 : 0.2;
    if (layers.surface.outline) actor.getProperty().setLineWidth(3);
    actor.getProperty().setOpacity(opacityDefault);
    checkbox(box, 'surface-visible', 'show', true, (on) => { actor.setVisibility(on); render(); });
    if (!layers.surface.outline) {
      const opacity = slider(box, 'surface-opacity', 'opacity', 0, 1, 0.01, opacityDefault, (v) => {
        actor.getProperty().setOpacity(v);
        render();
      });
      if (layers.surface.thickness) {
        const thickness = surface.getPointData().getArrayByName('Thickness').getData();
        const [lo, hi] = finiteRange(thickness);
        const tbox = fieldset(panel, 'Wall thickness', 'thickness');
        const readout = el('p', { className: 'note', id: 'thickness-readout' });
        const ctf = vtkColorTransferFunction.newInstance();
        ctf.setNanColor(0.6, 0.6, 0.6, 1);
        const paint = (threshold) => {
          // Thinner than the threshold: red; thicker: light to dark blue.
          ctf.removeAllPoints();
          const eps = Math.max(1e-12, 1e-6 * (hi - lo));
          ctf.addRGBPoint(lo - eps, ...THIN);
          ctf.addRGBPoint(Math.max(lo, threshold), ...THIN);
          ctf.addRGBPoint(Math.max(lo, threshold) + eps, 0.85, 0.9, 0.97);
          ctf.addRGBPoint(Math.max(hi, threshold + 2 * eps), 0.12, 0.3, 0.7);
          let thin = 0;
          let measured = 0;
          for (let i = 0; i < thickness.length; ++i) {
            if (Number.isFinite(thickness[i])) {
              measured += 1;
              if (thickness[i] <= threshold) thin += 1;
            }
          }
          readout.textContent = `thinner than ${format(threshold)}: ${format((100 * thin) / Math.max(1, measured), 3)}% of the vertices`;
          state.thinVertices = thin;
          render();
        };
        const colour = (on) => {
          if (on) {
            colourBy(mapper, 'Thickness', ctf);
            actor.getProperty().setOpacity(1);
            actor.getProperty().setColor(1, 1, 1);
          } else {
            mapper.setScalarVisibility(false);
            actor.getProperty().setColor(...SURFACE_GREY);
            actor.getProperty().setOpacity(Number(opacity.value));
          }
          render();
        };
        checkbox(tbox, 'thickness-visible', 'colour the surface by thickness', true, colour);
        slider(tbox, 'thickness-threshold', 'highlight thinner than', lo, hi, (hi - lo) / 200 || 1e-6, lo + 0.25 * (hi - lo), paint);
        tbox.appendChild(readout);
        tbox.appendChild(ramp('thickness-legend', [THIN, [0.85, 0.9, 0.97], [0.12, 0.3, 0.7]], lo, hi, 'thin', ''));
        paint(lo + 0.25 * (hi - lo));
        colour(true);
        state.layers.surface.thicknessRange = [lo, hi];
      }
    }
    pickables.push([actor, 'surface', (cellPick) => {
      const info = { kind: layers.surface.outline ? 'outline' : 'surface point', position: cellPick.position };
      const t = surface.getPointData().getArrayByName('Thickness');
      if (t && cellPick.pointId >= 0) {
        info.thickness = t.getData()[cellPick.pointId];
        const r = surface.getPointData().getArrayByName('MedialRadius');
        if (r) info.medialRadius = r.getData()[cellPick.pointId];
        info.vertex = cellPick.pointId;
      }
      return info;
    }]);
  }

  // The balls: spheres coloured by radius, sized by it, filtered by a radius range.
  if (data.balls) {
    const balls = data.balls;
    const info = layers.balls;
    const radius = balls.getPointData().getArrayByName('Radius').getData();
    const [lo, hi] = finiteRange(radius);
    const mapper = vtkSphereMapper.newInstance({ scaleArray: 'Radius' });
    colourBy(mapper, 'Radius', rampFunction(lo, hi));
    const actor = actorOf(mapper);
    renderer.addActor(register('balls', actor, { points: balls.getNumberOfPoints(), total: info.total, stride: info.stride }));
    const box = fieldset(panel, planar ? 'Medial disks' : 'Medial balls', 'balls');
    const count = el('p', { className: 'note', id: 'balls-readout' });
    let shown = [];
    let range = [lo, hi];
    const filter = () => {
      shown = [];
      for (let i = 0; i < radius.length; ++i) if (radius[i] >= range[0] && radius[i] <= range[1]) shown.push(i);
      mapper.setInputData(pointSubset(balls, shown, ['Radius', 'MedialPointType']));
      count.textContent = `${shown.length.toLocaleString('en')} of ${radius.length.toLocaleString('en')} shown`;
      state.layers.balls.shown = shown.length;
      render();
    };
    // Shown first only when nothing else stands for the medial axis (like --render).
    const ballsVisible = !(layers.surface && layers.surface.thickness) && !data.mesh && !data.graph;
    actor.setVisibility(ballsVisible);
    checkbox(box, 'balls-visible', 'show', ballsVisible, (on) => { actor.setVisibility(on); render(); });
    const sizeDefault = planar ? 0.08 : 0.15;
    mapper.setScaleFactor(sizeDefault);
    slider(box, 'balls-size', 'size (share of the radius; 1: the true ball)', 0.01, 1, 0.01, sizeDefault, (v) => {
      mapper.setScaleFactor(v);
      render();
    });
    const step = (hi - lo) / 200 || 1e-6;
    // At its end a slider means no bound (its value is rounded when written out).
    slider(box, 'balls-min', 'smallest radius shown', lo, hi, step, lo, (v) => {
      range[0] = v <= lo + step / 2 ? -Infinity : v;
      filter();
    });
    slider(box, 'balls-max', 'largest radius shown', lo, hi, step, hi, (v) => {
      range[1] = v >= hi - step / 2 ? Infinity : v;
      filter();
    });
    box.appendChild(count);
    box.appendChild(ramp('balls-legend', RADIUS_RAMP, lo, hi, 'Radius', ''));
    if (info.stride > 1) {
      box.appendChild(el('p', { className: 'note warn', id: 'balls-decimation' },
        `This run has ${info.total.toLocaleString('en')} balls; to stay responsive the page shows one in every ` +
        `${info.stride} (${radius.length.toLocaleString('en')}): at most ${info.maximum.toLocaleString('en')} ` +
        '(vtkMedialHTMLWriter MaximumNumberOfBalls).'));
    }
    filter();
    const types = balls.getPointData().getArrayByName('MedialPointType');
    pickables.push([actor, 'balls', (pointPick) => {
      const id = shown[pointPick.pointId];
      const type = types ? types.getData()[id] : undefined;
      return {
        kind: planar ? 'disk' : 'ball',
        index: id * info.stride,
        position: Array.from(balls.getPoints().getPoint(id)),
        radius: radius[id],
        type: type === undefined ? 'unclassified' : (planar ? TYPES_2D : TYPES_3D)[type][0],
      };
    }]);
  }

  // The medial mesh: faces and edges by point type, seams and junctions on top.
  if (data.mesh) {
    const mesh = data.mesh;
    const box = fieldset(panel, 'Medial mesh', 'mesh');
    const ctf = categoryFunction(TYPES_3D);
    const types = mesh.getPointData().getArrayByName('MedialPointType').getData();
    const radius = mesh.getPointData().getArrayByName('Radius').getData();
    const parts = [['faces', 'polys', true], ['edges', 'lines', true]];
    parts.forEach(([name, cells, on]) => {
      const part = meshPart(mesh, cells);
      const mapper = vtkMapper.newInstance();
      mapper.setInputData(part);
      colourBy(mapper, 'MedialPointType', ctf);
      const actor = actorOf(mapper);
      if (cells === 'lines') actor.getProperty().setLineWidth(2);
      renderer.addActor(register(`mesh-${name}`, actor, { cells: cells === 'polys' ? mesh.getPolys().getNumberOfCells() : mesh.getLines().getNumberOfCells() }));
      checkbox(box, `mesh-${name}`, name === 'faces' ? 'faces' : 'edges (1D parts)', on, (v) => { actor.setVisibility(v); render(); });
    });
    [[2, 'seams', 0.006], [3, 'junctions', 0.01]].forEach(([code, name, size]) => {
      const ids = indicesOfType(types, code);
      const mapper = vtkSphereMapper.newInstance();
      mapper.setInputData(pointSubset(mesh, ids, []));
      const diagonal = Math.hypot(...[0, 1, 2].map((k) => mesh.getBounds()[2 * k + 1] - mesh.getBounds()[2 * k]));
      mapper.setRadius(size * diagonal);
      mapper.setScalarVisibility(false);
      const actor = actorOf(mapper, TYPES_3D[code][1]);
      renderer.addActor(register(`mesh-${name}`, actor, { points: ids.length }));
      checkbox(box, `mesh-${name}`, `${name} (${ids.length.toLocaleString('en')} vertices)`, true, (v) => { actor.setVisibility(v); render(); });
    });
    const counts = TYPES_3D.map((t, code) => indicesOfType(types, code).length);
    box.appendChild(legendRows('mesh-legend', TYPES_3D.map(([n, rgb], code) => [rgb, `${n}: ${counts[code].toLocaleString('en')}`])));
    box.appendChild(el('p', { className: 'note' },
      `${mesh.getNumberOfPoints().toLocaleString('en')} vertices, ${mesh.getLines().getNumberOfCells().toLocaleString('en')} edges, ` +
      `${mesh.getPolys().getNumberOfCells().toLocaleString('en')} faces`));
    pickables.push([state.layers['mesh-faces'].actor, 'mesh', (pick) => {
      const id = pick.pointId;
      return { kind: 'medial vertex', index: id, position: Array.from(mesh.getPoints().getPoint(id)), radius: radius[id], type: TYPES_3D[types[id]][0] };
    }, true]);
  }

  // The 2D graph: arcs by type, junctions and end points, and the junctions' disks.
  let normalRight = null;
  let normalUp = null;
  if (manifest.view) {
    normalUp = manifest.view.up;
    normalRight = cross(manifest.view.up, manifest.view.toward);
  }
  if (data.graph) {
    const graph = data.graph;
    const box = fieldset(panel, 'Medial graph', 'graph');
    const types = graph.getPointData().getArrayByName('MedialPointType').getData();
    const radius = graph.getPointData().getArrayByName('Radius').getData();
    const arcs = vtkPolyData.newInstance();
    arcs.setPoints(graph.getPoints());
    arcs.setLines(graph.getLines());
    arcs.getCellData().addArray(graph.getCellData().getArrayByName('ArcType'));
    const arcMapper = vtkMapper.newInstance();
    arcMapper.setInputData(arcs);
    colourBy(arcMapper, 'ArcType', categoryFunction(ARCS), true);
    const arcActor = actorOf(arcMapper);
    arcActor.getProperty().setLineWidth(3);
    renderer.addActor(register('graph-arcs', arcActor, { cells: graph.getLines().getNumberOfCells() }));
    checkbox(box, 'graph-arcs', 'arcs', true, (v) => { arcActor.setVisibility(v); render(); });
    const b = graph.getBounds();
    const diagonal = Math.hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]);
    const nodeActors = [];
    [[2, 0.012], [0, 0.009]].forEach(([code, size]) => {
      const ids = indicesOfType(types, code);
      const mapper = vtkSphereMapper.newInstance({ radius: size * diagonal, scalarVisibility: false });
      mapper.setInputData(pointSubset(graph, ids, []));
      const actor = actorOf(mapper, TYPES_2D[code][1]);
      nodeActors.push(actor);
      renderer.addActor(register(code === 2 ? 'graph-junctions' : 'graph-ends', actor, { points: ids.length }));
    });
    checkbox(box, 'graph-nodes', 'junctions and end points', true, (v) => { nodeActors.forEach((a) => a.setVisibility(v)); render(); });
    const junctions = indicesOfType(types, 2).sort((p, q) => radius[q] - radius[p]).slice(0, 6);
    const disks = circles(junctions.map((i) => graph.getPoints().getPoint(i)), junctions.map((i) => radius[i]), normalRight, normalUp);
    const diskMapper = vtkMapper.newInstance({ scalarVisibility: false });
    diskMapper.setInputData(disks);
    const diskActor = actorOf(diskMapper, [0.55, 0.55, 0.6]);
    diskActor.getProperty().setLineWidth(1.5);
    renderer.addActor(register('graph-disks', diskActor, { cells: junctions.length }));
    checkbox(box, 'graph-disks', 'maximal disks of the largest junctions', true, (v) => { diskActor.setVisibility(v); render(); });
    const count = (code) => indicesOfType(types, code).length;
    box.appendChild(legendRows('graph-legend', [
      [ARCS[0][1], `linear arcs`], [ARCS[1][1], `parabolic arcs`],
      [TYPES_2D[2][1], `junctions: ${count(2)}`], [TYPES_2D[0][1], `end points: ${count(0)}`]]));
    pickables.push([arcActor, 'graph', (pick) => {
      const id = pick.pointId;
      return { kind: 'graph point', index: id, position: Array.from(graph.getPoints().getPoint(id)), radius: radius[id], type: TYPES_2D[types[id]][0] };
    }]);
  }

  // The reconstruction, in a second view beside the input.
  let rebuilt = null;
  if (data.reconstruction) {
    rebuilt = vtkRenderer.newInstance({ background: [1, 1, 1] });
    const mapper = vtkMapper.newInstance({ scalarVisibility: false });
    mapper.setInputData(data.reconstruction);
    rebuilt.addActor(register('reconstruction', actorOf(mapper, COPPER), { points: data.reconstruction.getNumberOfPoints(), cells: data.reconstruction.getNumberOfCells() }));
    renderWindow.addRenderer(rebuilt);
    rebuilt.setActiveCamera(renderer.getActiveCamera());
    const box = fieldset(panel, 'Reconstruction', 'reconstruction');
    const split = (on) => {
      renderer.setViewport(0, 0, on ? 0.5 : 1, 1);
      rebuilt.setViewport(on ? 0.5 : 1, 0, 1, 1);
      rebuilt.setDraw(on);
      state.layers.reconstruction.actor.setVisibility(on);
      render();
    };
    checkbox(box, 'reconstruction-visible', 'the union of the balls, beside the input (same camera)', true, split);
    split(true);
  }

  // The pick marker: the picked ball as a translucent sphere, or a small dot.
  const markerMapper = vtkSphereMapper.newInstance({ scalarVisibility: false });
  const markerActor = actorOf(markerMapper, [1, 0.85, 0]);
  markerActor.getProperty().setOpacity(0.45);
  markerActor.setVisibility(false);
  markerActor.setPickable(false);
  renderer.addActor(markerActor);

  // Picking: the nearest hit along the ray among balls, medial vertices, graph points
  // and the surface.
  const pickBox = fieldset(panel, 'Picked', 'pick');
  const pickText = el('div', { id: 'medial-pick' }, planar ? 'Click a disk, the graph or the outline.' : 'Click a ball, the medial mesh or the surface.');
  pickBox.appendChild(pickText);
  const pointPicker = vtkPointPicker.newInstance();
  pointPicker.setPickFromList(true);
  pointPicker.setTolerance(0.008);
  const cellPicker = vtkCellPicker.newInstance();
  cellPicker.setPickFromList(true);
  const pickAt = (x, y) => {
    const camera = renderer.getActiveCamera();
    const eye = camera.getPosition();
    const hits = [];
    for (const [actor, kind, describe, byPoint] of pickables) {
      if (!actor.getVisibility()) continue;
      if (kind === 'surface' && !(layers.surface && layers.surface.outline)) {
        cellPicker.initializePickList();
        cellPicker.addPickList(actor);
        cellPicker.pick([x, y, 0], renderer);
        if (cellPicker.getActors().length && cellPicker.getCellId() >= 0) {
          const position = cellPicker.getPickPosition();
          const surface = data.surface;
          const cell = surface.getCellPoints(cellPicker.getCellId()).cellPointIds;
          let best = -1;
          let bestDistance = Infinity;
          cell.forEach((id) => {
            const p = surface.getPoints().getPoint(id);
            const d = Math.hypot(p[0] - position[0], p[1] - position[1], p[2] - position[2]);
            if (d < bestDistance) { bestDistance = d; best = id; }
          });
          hits.push({ distance: Math.hypot(...position.map((v, k) => v - eye[k])), info: describe({ position, pointId: best }) });
        }
      } else if (kind !== 'surface' || byPoint) {
        pointPicker.initializePickList();
        pointPicker.addPickList(actor);
        pointPicker.pick([x, y, 0], renderer);
        if (pointPicker.getActors().length && pointPicker.getPointId() >= 0) {
          const position = pointPicker.getPickPosition();
          hits.push({ distance: Math.hypot(...position.map((v, k) => v - eye[k])), info: describe({ pointId: pointPicker.getPointId() }) });
        }
      }
    }
    hits.sort((a, b) => a.distance - b.distance);
    const hit = hits.length ? hits[0].info : null;
    if (!hit) {
      pickText.textContent = 'Nothing here.';
      markerActor.setVisibility(false);
    } else {
      const lines = [hit.kind + (hit.index !== undefined ? ` #${hit.index}` : '')];
      lines.push(`position ${hit.position.map((v) => format(v)).join(', ')}`);
      if (hit.radius !== undefined) lines.push(`radius   ${format(hit.radius)}`);
      if (hit.type !== undefined) lines.push(`type     ${hit.type}`);
      if (hit.thickness !== undefined) lines.push(`thickness ${format(hit.thickness)}`);
      if (hit.medialRadius !== undefined) lines.push(`inscribed radius ${format(hit.medialRadius)}`);
      pickText.textContent = lines.join('\n');
      const marker = vtkPolyData.newInstance();
      marker.setPoints(vtkPoints.newInstance({ values: Float32Array.from(hit.position), numberOfComponents: 3 }));
      markerMapper.setInputData(marker);
      const b = renderer.computeVisiblePropBounds();
      const diagonal = Math.hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]);
      markerMapper.setRadius(hit.radius !== undefined ? hit.radius : 0.01 * diagonal);
      markerActor.setVisibility(true);
    }
    state.picked = hit;
    render();
    return hit;
  };
  // A click (press and release within a few pixels) picks; a drag turns the view.
  let pressed = null;
  interactor.onLeftButtonPress((e) => { pressed = e.position; });
  interactor.onLeftButtonRelease((e) => {
    if (pressed && Math.hypot(e.position.x - pressed.x, e.position.y - pressed.y) < 4) pickAt(e.position.x, e.position.y);
    pressed = null;
  });

  // The opening view: vtkMedialScene's directions, and its framing: the extent of what is
  // drawn across and up fills the view but for a margin.
  const camera = renderer.getActiveCamera();
  const frame = () => {
    const up = manifest.view ? manifest.view.up : [0, 1, 0];
    const toward = manifest.view ? manifest.view.toward : [0, 0, 1];
    const right = cross(up, toward);
    const b = renderer.computeVisiblePropBounds();
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    for (let corner = 0; corner < 8; ++corner) {
      const p = [b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)]];
      [right, up, toward].forEach((axis, k) => {
        const t = p[0] * axis[0] + p[1] * axis[1] + p[2] * axis[2];
        lo[k] = Math.min(lo[k], t);
        hi[k] = Math.max(hi[k], t);
      });
    }
    const centre = [0, 1, 2].map((c) => [right, up, toward].reduce((sum, axis, k) => sum + 0.5 * (lo[k] + hi[k]) * axis[c], 0));
    const [w, h] = glWindow.getViewportSize(renderer);
    const aspect = w > 0 && h > 0 ? w / h : 1;
    const half = (0.5 * Math.max(hi[1] - lo[1], (hi[0] - lo[0]) / aspect)) / 0.9 || 1;
    const depth = hi[2] - lo[2];
    camera.setParallelProjection(planar);
    camera.setViewAngle(30);
    const distance = planar ? Math.max(depth, half) * 2 : half / Math.tan(Math.PI / 12) + 0.5 * depth;
    camera.setFocalPoint(...centre);
    camera.setPosition(...centre.map((c, k) => c + distance * toward[k]));
    camera.setViewUp(...up);
    camera.setParallelScale(half);
    renderer.resetCameraClippingRange();
    render();
  };
  const reset = el('button', { id: 'reset-camera', type: 'button' }, 'Reset the view');
  reset.addEventListener('click', frame);
  panel.appendChild(reset);
  panel.appendChild(el('p', { className: 'credit' },
    `Made by medialaxis (vtkMedialHTMLWriter) with vtk.js ${manifest.vtkjs || ''}. ` +
    'Everything this page shows is inside it: it works offline. Drag to turn (2D: to pan), wheel to zoom, click to pick.'));

  window.addEventListener('resize', resize);
  resize();
  frame();
  renderWindow.render();

  state.controls = Array.from(panel.querySelectorAll('input, button')).map((n) => n.id);
  window.medialViewer = {
    manifest,
    state,
    renderWindow,
    renderer,
    // Picks at a fraction of the view's width and height from its lower left corner.
    pick(fx, fy) {
      const [w, h] = glWindow.getSize();
      return pickAt(fx * w, fy * h);
    },
    render: () => renderWindow.render(),
    // The page (CSS pixel) position of point `index` of a layer's dataset ('front': its
    // point nearest the camera), or null when it lies outside the view: where a click
    // picks it.
    screenOf(layer, index) {
      if (!data[layer]) return null;
      const points = data[layer].getPoints();
      if (index === 'front') {
        const eye = renderer.getActiveCamera().getPosition();
        let best = Infinity;
        for (let i = 0; i < points.getNumberOfPoints(); ++i) {
          const q = points.getPoint(i);
          const d = Math.hypot(q[0] - eye[0], q[1] - eye[1], q[2] - eye[2]);
          if (d < best) { best = d; index = i; }
        }
      }
      const p = points.getPoint(index);
      const [x, y] = glWindow.worldToDisplay(p[0], p[1], p[2], renderer);
      const [w, h] = glWindow.getSize();
      const box = view.getBoundingClientRect();
      if (x < 0 || y < 0 || x > w || y > h) return null;
      return { x: box.left + (x * box.width) / w, y: box.top + ((h - y) * box.height) / h };
    },
    layers() {
      const out = {};
      Object.entries(state.layers).forEach(([name, layer]) => {
        const { actor, ...rest } = layer;
        out[name] = { visible: !!actor.getVisibility(), ...rest };
      });
      return out;
    },
  };
  document.documentElement.dataset.medialStatus = 'ready';
}

main().catch(fail);
