using System.CommandLine;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// The handler options a station's handler can be generated with, defined once for <c>opanel generate</c> and
/// <c>opanel simulate</c> so a simulated station runs exactly the handler generate writes for the same options. Text
/// that cannot be read (not a V byte, an unknown area) is bad input here; readable but impossible values pass into
/// <see cref="HandlerOptions"/> for <see cref="StlGen.Diagnostics.HandlerOptionsCheck"/> to report with their STL IDs.
/// </summary>
internal sealed class HandlerOptionSet
{
    public Option<int> Protocol { get; } = new("--protocol")
    {
        Description = "Protocol version of the handler: 3 (binary frames, docs/protocol.md: what the panel speaks; default) or 2 "
            + "(the previous hex frames: the panel tells such a station to regenerate its PLC code)",
        DefaultValueFactory = _ => 3,
    };

    public Option<bool> Compact { get; } = new("--compact")
    {
        Description = "The compact handler of protocol 3 (IDENTIFY, READ, WRITE, WRITE BITS; no list, no STOP): the choice for a CPU 221 or 222 "
            + "(default: the station's \"compact\" in the project, which opanel project new and the wizard set for those CPUs; "
            + "--compact false gives such a station the full handler, as does --protocol 2; with STOP allowed, by --allow-stop or the project's \"allowStop\", "
            + "it is refused, STL031: the compact handler has no STOP)",
    };

    public Option<int> PlcPort { get; } = new("--plc-port") { Description = "The PLC's port 0 or 1 (port 1 on CPU 224XP and 226)" };

    public Option<string?> Buffer { get; } = new("--buffer")
    {
        Description = "First V byte of the handler's bytes (buffer, work bytes, copies), e.g. VB1000 (default: the station's \"handlerVFirst\" "
            + "in the project, else the top of V memory; record a --buffer there so the panel's write rules keep off the handler's bytes)",
    };

    public Option<int> ReplyDelay { get; } = new("--reply-delay") { Description = "Protocol 2 only: reply delay in ms, 1-255 (default 5)", DefaultValueFactory = _ => 5 };

    public Option<string> Writable { get; } = new("--writable")
    {
        Description = "Areas the panel may write, e.g. Q,M,V,SM (default; protocol 3 never writes SM: Q, M and V of the list count)",
        DefaultValueFactory = _ => "Q,M,V,SM",
    };

    public Option<int> CharTimeout { get; } = new("--char-timeout")
    {
        Description = "Receive inter-character timeout in ms. Protocol 3: END_TIMEOUT_MS, the receive ends this long after the last "
            + "character (0 = default: one character + 2 ms, at least the cable's turnaround; 4 ms at 9600 baud). Protocol 2: 0 = off (default)",
    };

    public Option<int?> Subroutine { get; } = new("--sbr") { Description = "Subroutine number of the handler (default: the CPU's last)" };

    public Option<int?> Interrupt { get; } = new("--int") { Description = "First of the handler's interrupt routines: 2 in protocol 3 (receive, transmit complete), 3 in protocol 2 (default 125)" };

    public Option<int> CopyBytes { get; } = new("--copy-bytes")
    {
        Description = "Protocol 2 only: V bytes for READ CHANGES copies after the work bytes, 0-255 (0 = none: every READ CHANGES answers the whole list; default 120)",
        DefaultValueFactory = _ => HandlerDefaults.CopyBytes,
    };

    public Option<bool> AllowStop { get; } = new("--allow-stop")
    {
        Description = "Include STOP (08 in protocol 3, 07 in 2): the panel may put the CPU in STOP (default: the station's \"allowStop\" in the "
            + "project, off unless set; --allow-stop false leaves it out of a station whose project allows it; off = no STOP code, the command is refused: 85 in protocol 3, error 05 in 2; refused with a compact handler, STL031)",
    };

    private Option[] All => [Protocol, Compact, PlcPort, Buffer, ReplyDelay, Writable, CharTimeout, Subroutine, Interrupt, CopyBytes, AllowStop];

    public void AddTo(Command command)
    {
        foreach (var option in All)
        {
            command.Options.Add(option);
        }
    }

    /// <summary>The name of the first handler option given on the command line, or null when none was.</summary>
    public string? Given(ParseResult parse) => All.FirstOrDefault(o => parse.GetResult(o) is { Implicit: false })?.Name;

    /// <summary>
    /// <paramref name="station"/> (CPU, address, line settings, "allowStop", "compact" and "handlerVFirst" from the project or --cpu/--station)
    /// with the options given; --allow-stop adds STOP and does not remove a project's. --compact (true or false) wins over
    /// the project's "compact", which a CPU 221 or 222 gets by default; --compact implies protocol 3, and an explicit
    /// --protocol 2 leaves the project's "compact" aside (protocol 2 has one shape). The options only protocol 2 has are
    /// refused with protocol 3.
    /// </summary>
    public bool TryApply(ParseResult parse, HandlerOptions station, [NotNullWhen(true)] out HandlerOptions? options, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(parse);
        ArgumentNullException.ThrowIfNull(station);
        options = null;
        var given = parse.GetResult(Protocol) is { Implicit: false };
        var compact = parse.GetResult(Compact) is { Implicit: false }
            ? parse.GetValue(Compact)
            : station.Compact && !(given && parse.GetValue(Protocol) == 2);
        var protocol = compact && !given ? 3 : parse.GetValue(Protocol);
        if (protocol is not (2 or 3))
        {
            error = $"--protocol {protocol}: the handler speaks protocol 3 (or the previous 2)";
            return false;
        }

        if (protocol == 2 && compact)
        {
            error = "--compact is a protocol 3 handler: leave out --protocol 2 (or --compact)";
            return false;
        }

        if (protocol == 3 && new Option[] { ReplyDelay, CopyBytes }.FirstOrDefault(o => parse.GetResult(o) is { Implicit: false }) is { } v2Only)
        {
            error = $"{v2Only.Name} is a protocol 2 option; a protocol 3 handler has no reply delay (END_TIMEOUT_MS, --char-timeout, holds the reply back) and no READ CHANGES copies";
            return false;
        }

        if (!GenerateSettings.TryParseWritable(parse.GetValue(Writable)!, out var mask, out error))
        {
            return false;
        }

        // --buffer wins over the project's "handlerVFirst" (in station.BufferStart), which wins over the top of V; the
        // project's place is its protocol 3 handler's, so protocol 2 (another layout) leaves it aside as it does "compact".
        var start = protocol == 3 ? station.BufferStart : null;
        if (parse.GetValue(Buffer) is { } bufferText)
        {
            if (!GenerateSettings.TryParseBuffer(bufferText, out var at, out error))
            {
                return false;
            }

            start = at;
        }

        options = station with
        {
            Protocol = protocol,
            Compact = compact,
            Port = parse.GetValue(PlcPort),
            BufferStart = start,
            WriteMask = mask,
            ReplyDelayMs = parse.GetValue(ReplyDelay),
            CharTimeoutMs = parse.GetValue(CharTimeout),
            FirstSubroutine = parse.GetValue(Subroutine),
            FirstInterrupt = parse.GetValue(Interrupt),
            CopyBytes = parse.GetValue(CopyBytes),
            AllowStop = parse.GetResult(AllowStop) is { Implicit: false } ? parse.GetValue(AllowStop) : station.AllowStop,
        };
        return true;
    }
}
