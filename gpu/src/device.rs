//! Running a compute shader through `wgpu` on whatever adapter it finds.

use wgpu::util::DeviceExt;

/// The adapter, device and queue.
pub struct Gpu {
    /// What wgpu reports of the adapter (name, driver, driver info, backend).
    pub info: wgpu::AdapterInfo,
    device: wgpu::Device,
    queue: wgpu::Queue,
}

impl Gpu {
    /// The first adapter wgpu finds on any native back end (Vulkan here), preferring a
    /// discrete GPU; `None` where there is none.
    #[must_use]
    pub fn new() -> Option<Self> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::VULKAN,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            force_fallback_adapter: false,
            compatible_surface: None,
            ..wgpu::RequestAdapterOptions::default()
        }))
        .ok()?;
        let info = adapter.get_info();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("brdf-gpu"),
            required_limits: adapter.limits(),
            ..wgpu::DeviceDescriptor::default()
        }))
        .ok()?;
        Some(Self {
            info,
            device,
            queue,
        })
    }

    /// The wgpu device, for callers building their own pipelines.
    #[must_use]
    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// One line naming the adapter: name, driver, driver info, back end, device type.
    #[must_use]
    pub fn describe(&self) -> String {
        let i = &self.info;
        format!(
            "{} (driver {} {}, {:?}, {:?})",
            i.name, i.driver, i.driver_info, i.backend, i.device_type
        )
    }

    /// Runs `source`'s entry point `main` (bindings 0: the inputs, 1: the outputs, both
    /// `array<f32>`) over `n` rows, returning `n * outputs_per_row` values.
    ///
    /// # Panics
    /// If wgpu reports an error (shader compilation, mapping).
    #[must_use]
    pub fn run(&self, source: &str, inputs: &[f32], n: usize, outputs_per_row: usize) -> Vec<f32> {
        let d = &self.device;
        let module = d.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: None,
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let pipeline = d.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: None,
            layout: None,
            module: &module,
            entry_point: Some("main"),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            cache: None,
        });
        // A storage binding may not be empty.
        let input_bytes: Vec<u8> = if inputs.is_empty() {
            vec![0; 4]
        } else {
            inputs.iter().flat_map(|x| x.to_le_bytes()).collect()
        };
        let input = d.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents: &input_bytes,
            usage: wgpu::BufferUsages::STORAGE,
        });
        let size = (n * outputs_per_row * 4) as u64;
        let output = d.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readback = d.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind = d.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: input.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: output.as_entire_binding(),
                },
            ],
        });
        let mut enc = d.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
        {
            let mut pass = enc.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &bind, &[]);
            let groups = u32::try_from(n.div_ceil(crate::shaders::WORKGROUP as usize))
                .expect("rows fit one dispatch");
            pass.dispatch_workgroups(groups, 1, 1);
        }
        enc.copy_buffer_to_buffer(&output, 0, &readback, 0, size);
        self.queue.submit([enc.finish()]);
        readback.map_async(wgpu::MapMode::Read, .., |r| r.expect("maps"));
        d.poll(wgpu::PollType::wait_indefinitely())
            .expect("the device finishes");
        let view = readback.get_mapped_range(..).expect("mapped");
        let out = view
            .chunks_exact(4)
            .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
            .collect();
        drop(view);
        readback.unmap();
        out
    }
}
