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
    public Option<int> PlcPort { get; } = new("--plc-port") { Description = "The PLC's port 0 or 1 (port 1 on CPU 224XP and 226)" };

    public Option<string?> Buffer { get; } = new("--buffer")
    {
        Description = "First V byte of the handler's bytes (buffer, work bytes, copies), e.g. VB1000 (default: the top of V memory)",
    };

    public Option<int> ReplyDelay { get; } = new("--reply-delay") { Description = "Reply delay in ms, 1-255 (default 5)", DefaultValueFactory = _ => 5 };

    public Option<string> Writable { get; } = new("--writable")
    {
        Description = "Areas the panel may write, e.g. Q,M,V,SM (default)",
        DefaultValueFactory = _ => "Q,M,V,SM",
    };

    public Option<int> CharTimeout { get; } = new("--char-timeout") { Description = "Receive inter-character timeout in ms (0 = off, default)" };

    public Option<int?> Subroutine { get; } = new("--sbr") { Description = "Subroutine number of the handler (default: the CPU's last)" };

    public Option<int?> Interrupt { get; } = new("--int") { Description = "First of the handler's 3 interrupt routines (default 125)" };

    public Option<int> CopyBytes { get; } = new("--copy-bytes")
    {
        Description = "V bytes for READ CHANGES copies after the work bytes, 0-255 (0 = none: every READ CHANGES answers the whole list; default 120)",
        DefaultValueFactory = _ => HandlerDefaults.CopyBytes,
    };

    public Option<bool> AllowStop { get; } = new("--allow-stop")
    {
        Description = "Include 07 STOP: the panel may put the CPU in STOP (default: the station's \"allowStop\" in the project, off unless set; "
            + "off = no STOP code, the command is refused with error 05)",
    };

    private Option[] All => [PlcPort, Buffer, ReplyDelay, Writable, CharTimeout, Subroutine, Interrupt, CopyBytes, AllowStop];

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
    /// <paramref name="station"/> (CPU, address, line settings and "allowStop" from the project or --cpu/--station) with the
    /// options given; --allow-stop adds STOP, it never removes a project's.
    /// </summary>
    public bool TryApply(ParseResult parse, HandlerOptions station, [NotNullWhen(true)] out HandlerOptions? options, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(parse);
        ArgumentNullException.ThrowIfNull(station);
        options = null;
        if (!GenerateSettings.TryParseWritable(parse.GetValue(Writable)!, out var mask, out error))
        {
            return false;
        }

        int? start = null;
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
            Port = parse.GetValue(PlcPort),
            BufferStart = start,
            WriteMask = mask,
            ReplyDelayMs = parse.GetValue(ReplyDelay),
            CharTimeoutMs = parse.GetValue(CharTimeout),
            FirstSubroutine = parse.GetValue(Subroutine),
            FirstInterrupt = parse.GetValue(Interrupt),
            CopyBytes = parse.GetValue(CopyBytes),
            AllowStop = station.AllowStop || parse.GetValue(AllowStop),
        };
        return true;
    }
}
