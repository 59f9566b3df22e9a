using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>One PLC of a line: where it sits on the bus, its CPU, and what the panel shows of it.</summary>
/// <param name="Name">Unique within the project, e.g. "Filler".</param>
/// <param name="Address">RS-485 station address; unique among the stations on one port.</param>
/// <param name="Cpu">The CPU model and revision every address of this station is checked against.</param>
/// <param name="Link">The PC's serial port and its Freeport settings; stations on one port share them.</param>
/// <param name="Inputs">Symbols for I bits (the "Input" window).</param>
/// <param name="Outputs">Symbols for Q bits (the "Output" window, where the operator may also set them).</param>
/// <param name="Tags">Memory cells shown in the PLC memory window.</param>
/// <param name="Alarms">Flag bits whose rising state shows a message.</param>
/// <remarks>
/// <see cref="AllowStop"/> ("allowStop" in the file, default false) and <see cref="Compact"/> ("compact", default false)
/// are init properties so the many stations built in code keep their shape; so is <see cref="HandlerVFirst"/>
/// ("handlerVFirst", absent by default).
/// </remarks>
public sealed record ProjectStation(
    string Name,
    Station Address,
    CpuProfile Cpu,
    SerialSettings Link,
    ImmutableArray<IoSymbol> Inputs,
    ImmutableArray<IoSymbol> Outputs,
    ImmutableArray<ProjectTag> Tags,
    ImmutableArray<AlarmDefinition> Alarms)
{
    /// <summary>
    /// The station's handler is generated with 07 STOP (HandlerOptions.AllowStop) and the panel offers Stop for it. Off
    /// by default: a remote STOP halts the line (docs/protocol-v2.md, "07 STOP"). Not with <see cref="Compact"/>: the
    /// compact handler has no STOP (<see cref="CompactStop"/>).
    /// </summary>
    public bool AllowStop { get; init; }

    /// <summary>
    /// The station's handler is the compact protocol 3 handler (IDENTIFY, READ, WRITE, WRITE BITS; no list, no STOP:
    /// 178 V bytes and about half the instructions, docs/protocol.md section 6), the choice for a CPU 221 or 222 whose
    /// 4096 bytes of program memory the full handler would crowd. The panel reads such a station with READ; opanel
    /// generate and Generate PLC code honour it. Off by default, and old project files (without "compact") load unchanged.
    /// </summary>
    public bool Compact { get; init; }

    /// <summary>
    /// V_FIRST: the first V byte of the station's handler when it was generated somewhere other than the default place
    /// (<c>opanel generate --buffer VB1000</c> records nothing in the PLC's program that the panel could read before it
    /// sends); null = the default place, the top of V (<see cref="Protocol.V3.HandlerShape.DefaultVFirst"/>). The write
    /// rules keep off the handler's bytes from here, and generate, simulate and the demo line put the handler here.
    /// The project file's reader checks it with the generator's rule (<see cref="Protocol.V3.HandlerPlace"/>).
    /// </summary>
    public int? HandlerVFirst { get; init; }

    /// <summary>The symbol the project gives <paramref name="address"/> (an output, input or tag; the first tag of several); null if none.</summary>
    public string? SymbolOf(PlcAddress address) =>
        Outputs.FirstOrDefault(s => s.Address == address)?.Symbol
        ?? Inputs.FirstOrDefault(s => s.Address == address)?.Symbol
        ?? Tags.FirstOrDefault(t => t.Address == address)?.Symbol;
}
