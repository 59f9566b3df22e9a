using System.Collections.Immutable;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Diagnostics;

/// <summary>Checks <see cref="HandlerOptions"/> against the CPU; every problem is one diagnostic, never an exception.</summary>
public static partial class HandlerOptionsCheck
{
    public static ImmutableArray<StlDiagnostic> Check(HandlerOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        var found = ImmutableArray.CreateBuilder<StlDiagnostic>();
        void Add(string id, string message) => found.Add(new StlDiagnostic(id, message));
        var cpu = options.Cpu;

        if (options.Port < 0 || options.Port >= cpu.CommunicationPorts)
        {
            Add(StlDiagnostics.PortNotOnCpu, $"port {options.Port} is not on the {cpu.DisplayName}; allowed: {(cpu.CommunicationPorts == 1 ? "port 0" : "port 0 or 1")}");
        }

        if (cpu.FreeportBaudCode(options.BaudRate) is null)
        {
            Add(StlDiagnostics.BaudNotAllowed, $"{options.BaudRate} baud is not a Freeport rate of the {cpu.DisplayName}; allowed: {string.Join(", ", cpu.FreeportBaudRates.Select(r => r.Baud).Order())}");
        }

        if (options.DataBits is not (7 or 8))
        {
            Add(StlDiagnostics.DataBitsNotAllowed, $"{options.DataBits} data bits: SMB30 selects 7 or 8");
        }
        else if (options.DataBits == 7 && options.Protocol == 3)
        {
            // Protocol 3 frames carry binary bytes (and STATUS has bit 7 set): a 7-bit character loses their top bit.
            Add(StlDiagnostics.DataBitsNotAllowed, "7 data bits: protocol 3 frames are binary bytes and need 8 data bits (protocol 2's hex frames took 7)");
        }

        if (options.StopBits != 1)
        {
            Add(StlDiagnostics.StopBitsNotAllowed, $"{options.StopBits} stop bits: Freeport always uses 1");
        }

        if (!Enum.IsDefined(options.Parity))
        {
            Add(StlDiagnostics.ParityNotAllowed, $"parity {options.Parity}: SMB30 selects none, even or odd");
        }

        CheckBuffer(options, Add);

        if (options.Station is < Core.Addressing.Station.Min or > Core.Addressing.Station.Max)
        {
            Add(StlDiagnostics.StationOutOfRange, $"station address {options.Station} is outside 1-126");
        }

        if (options.ReplyDelayMs is < 1 or > 255)
        {
            Add(StlDiagnostics.ReplyDelayOutOfRange, $"reply delay {options.ReplyDelayMs} ms is outside 1-255 ms (SMB34)");
        }

        if (options.CharTimeoutMs is < 0 or > short.MaxValue)
        {
            Add(StlDiagnostics.CharTimeoutOutOfRange, $"inter-character timeout {options.CharTimeoutMs} ms is outside 0 (off) to 32767 ms (SMW92)");
        }

        CheckBlocks(options, Add);

        if (options.Protocol == 3 && CompactStop.Contradicts(options.Compact, options.AllowStop))
        {
            Add(StlDiagnostics.CompactHandlerHasNoStop, CompactStop.Describe($"station {options.Station}", CompactStopWords.File));
        }

        if ((options.WriteMask & ~HandlerDefaults.WriteMask) != 0)
        {
            Add(StlDiagnostics.WriteMaskNotAllowed, $"write mask 16#{options.WriteMask:X2} allows areas the panel may never write (I, or codes above 5); allowed: any of Q, M, V, SM (16#04, 16#08, 16#10, 16#20)");
        }

        return found.ToImmutable();
    }

    private static void CheckBuffer(HandlerOptions options, Action<string, string> add)
    {
        if (options.CopyBytes is < 0 or > 255)
        {
            add(StlDiagnostics.CopyBytesOutOfRange, $"{options.CopyBytes} copy bytes for READ CHANGES is outside 0 (none) to 255");
            return;
        }

        var vBytes = HandlerDefaults.VBytes(options.Cpu);
        if (options.Protocol == 3)
        {
            // Protocol 3 keeps V_BYTES of its full or compact shape from V_FIRST: Core's rule, which a project's
            // "handlerVFirst" passes too.
            var shape = HandlerShape.Of(options.Compact);
            if (HandlerPlace.Problem(options.EffectiveV3First, shape, options.Cpu) is { } problem)
            {
                add(StlDiagnostics.BufferOutsideV, $"{problem}; allowed buffer start: VB{HandlerPlace.LowestVFirst}-VB{HandlerPlace.HighestVFirst(shape, vBytes)}");
            }

            return;
        }

        // Protocol 2 keeps its buffer, work bytes and copies.
        var start = options.EffectiveBufferStart;
        var bytes = HandlerDefaults.FootprintBytes(options.CopyBytes);
        var end = start + bytes - 1;
        if (start < 0 || end >= vBytes)
        {
            add(StlDiagnostics.BufferOutsideV, $"the handler needs VB{start}-VB{end} ({bytes} bytes) but the {options.Cpu.DisplayName} has VB0-VB{vBytes - 1}; "
                + $"allowed buffer start: VB0-VB{vBytes - bytes}");
        }
    }

    private static void CheckBlocks(HandlerOptions options, Action<string, string> add)
    {
        var cpu = options.Cpu;
        var sbr = options.EffectiveFirstSubroutine;
        if (sbr < 0 || sbr >= cpu.Subroutines)
        {
            add(StlDiagnostics.SubroutineOutOfRange, $"SBR{sbr} is outside the {cpu.DisplayName}'s SBR0-SBR{cpu.Subroutines - 1}");
        }

        var first = options.EffectiveFirstInterrupt;
        var count = options.InterruptRoutines;
        if (first < 0 || first + count > cpu.InterruptRoutines)
        {
            add(StlDiagnostics.InterruptOutOfRange, $"INT{first}-INT{first + count - 1} are not all inside INT0-INT{cpu.InterruptRoutines - 1}; the first INT may be 0-{cpu.InterruptRoutines - count}");
        }

        var names = options.Names.All.ToList();
        foreach (var name in names.Where(n => !BlockName().IsMatch(n)))
        {
            add(StlDiagnostics.BlockNameInvalid, $"block name '{name}': use letters, digits and underscores, a letter first, at most 23 characters");
        }

        foreach (var name in names.GroupBy(n => n, StringComparer.OrdinalIgnoreCase).Where(g => g.Count() > 1 || g.Key.Equals("MAIN", StringComparison.OrdinalIgnoreCase)).Select(g => g.Key))
        {
            add(StlDiagnostics.BlockNamesOverlap, $"block name '{name}' is used twice or is OB1's name MAIN; every handler block needs its own name");
        }
    }

    [GeneratedRegex("^[A-Za-z][A-Za-z0-9_]{0,22}$")]
    private static partial Regex BlockName();
}
