using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Simulator.Stl.Ppi;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// One simulated S7-200 running an .awl program (the generated handler) in the STL interpreter, with a Freeport port on
/// the handler's port number. The demo process drives its memory as it drives the reference PLC's: inputs it writes
/// to I become the CPU's input image at the next scan, and an output the handler changed (a panel write) stays the
/// panel's, as <see cref="ReferencePlc.IsOwnedByPanel"/> keeps it.
/// </summary>
public sealed class StlStation : IDemoPlc
{
    private readonly byte[] _programOutputs;
    private readonly byte[] _panelOutputs;

    private StlStation(StlPlc plc, FreeportPort port)
    {
        Plc = plc;
        Port = port;
        _programOutputs = new byte[plc.Memory.Q.Length];
        _panelOutputs = new byte[plc.Memory.Q.Length];
    }

    public StlPlc Plc { get; }

    public FreeportPort Port { get; }

    public PlcMemory Memory => Plc.Memory;

    public OperatingMode Mode => Plc.Mode;

    /// <summary>
    /// Loads <paramref name="awlText"/> for <paramref name="cpu"/> and puts a Freeport port number
    /// <paramref name="port"/> on it; false with the loader's first diagnostic (line and message) when it does not load.
    /// </summary>
    public static bool TryCreate(string awlText, CpuProfile cpu, int port, LineSettings pcLine, [NotNullWhen(true)] out StlStation? station, out string error)
    {
        ArgumentNullException.ThrowIfNull(awlText);
        ArgumentNullException.ThrowIfNull(cpu);
        station = null;
        var loaded = StlProgramLoader.Load(awlText, cpu);
        if (!loaded.Succeeded)
        {
            error = loaded.Diagnostics.IsDefaultOrEmpty
                ? "the program did not load"
                : $"{loaded.Diagnostics.Length} load diagnostic(s), first: {loaded.Diagnostics[0]}";
            return false;
        }

        if (port < 0 || port >= cpu.CommunicationPorts)
        {
            error = $"{cpu.DisplayName} has no port {port}";
            return false;
        }

        var plc = new StlPlc(loaded.Program);
        var freeport = new FreeportPort(port, plc.Memory, cpu, pcLine);
        plc.AttachPort(freeport);
        station = new StlStation(plc, freeport);
        error = string.Empty;
        return true;
    }

    /// <summary>The CPU's PPI station on its port, or null (<see cref="AttachPpi"/>).</summary>
    public PpiSlave? Ppi { get; private set; }

    /// <summary>
    /// Gives the CPU its PPI side: whenever the program does not hold the port in Freeport, the port answers PPI
    /// telegrams for <paramref name="settings"/>' address, and the jobs are done in the scan's communication phase on
    /// the memory the program runs on.
    /// </summary>
    public PpiSlave AttachPpi(PpiSettings settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        var slave = new PpiSlave(settings);
        var memory = new StlPpiMemory(Plc);
        Port.AttachPpi(slave);
        Plc.StopCommunicationCycle = settings.StopCycle;
        Plc.CommunicationPhase += (_, _) => slave.Serve(memory);
        Ppi = slave;
        return slave;
    }

    /// <summary>Runs the CPU to <paramref name="until"/>; outputs the handler changed on the way become the panel's.</summary>
    public void RunUntil(TimeSpan until)
    {
        Plc.RunUntil(until);
        var q = Memory.Q;
        for (var i = 0; i < q.Length; i++)
        {
            _panelOutputs[i] |= (byte)(q[i] ^ _programOutputs[i]);
            _programOutputs[i] = q[i];
        }
    }

    /// <summary>The demo wrote the field inputs to I: the CPU reads them at its next scan. Scan times are the CPU's own.</summary>
    public void CompleteScan(ushort milliseconds)
    {
        Array.Copy(Memory.I, Plc.InputImage, Plc.InputImage.Length);
        Array.Copy(Memory.Q, _programOutputs, _programOutputs.Length);
    }

    public bool IsOwnedByPanel(int offset, int bit) => (_panelOutputs[offset] & (1 << bit)) != 0;
}
