export {
  ACESFilmicToneMapping, AmbientLight, Box3, BufferAttribute, BufferGeometry, Color, DirectionalLight,
  DoubleSide, Euler, Group, HemisphereLight, MathUtils, Mesh, MeshStandardMaterial, PCFShadowMap,
  PerspectiveCamera, PlaneGeometry, PMREMGenerator, Quaternion, RepeatWrapping, Scene, ShadowMaterial,
  SRGBColorSpace, Texture, TextureLoader, Vector3, WebGLRenderer, GridHelper, Matrix4, LinearMipmapLinearFilter,
  NoColorSpace
} from 'three';
export { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
export { RoomEnvironment } from 'three/examples/jsm/environments/RoomEnvironment.js';
