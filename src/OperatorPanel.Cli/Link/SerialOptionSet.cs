using System.CommandLine;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Link;

/// <summary>--device, --baud, --parity, --data-bits (and --radio for the panel's side): one serial line's settings.</summary>
internal sealed class SerialOptionSet
{
    /// <summary>S7-200 Freeport rates (SMB30 bits 4-2; 57600 and 115200 need a Current CPU; docs/cpu-profiles.md).</summary>
    private static readonly int[] FreeportRates = [1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200];

    /// <summary>The S7-200's PPI rates (seed 002, Tables A-2 to A-4: "PPI/MPI baud rates 9.6, 19.2, and 187.5 kbaud").</summary>
    private static readonly int[] PpiRates = [9600, 19200, 187500];

    private readonly bool _panelSide;

    /// <param name="panelSide">
    /// The panel's end of the line (read, write, identify, stop): --radio is offered, and --demo stands in for --device;
    /// false for the end simulate serves, which has neither.
    /// </param>
    public SerialOptionSet(bool panelSide) => _panelSide = panelSide;

    public Option<string?> Device { get; } = new("--device")
    {
        Description = "Serial port: COM3 on Windows, /dev/ttyUSB0 or /dev/pts/N on Linux",
    };

    public Option<int> Baud { get; } = new("--baud") { Description = "Baud rate, a Freeport rate (default 9600)", DefaultValueFactory = _ => 9600 };

    public Option<Parity> Parity { get; } = new("--parity") { Description = "none (default), even or odd", DefaultValueFactory = _ => Core.Transport.Parity.None };

    public Option<int> DataBits { get; } = new("--data-bits") { Description = "7 or 8 (default 8); one stop bit always", DefaultValueFactory = _ => 8 };

    public Option<bool> Radio { get; } = new("--radio") { Description = "The port is the 433 MHz radio module (longer timeouts, more retries)" };

    public void AddTo(Command command)
    {
        command.Options.Add(Device);
        command.Options.Add(Baud);
        command.Options.Add(Parity);
        command.Options.Add(DataBits);
        if (_panelSide)
        {
            command.Options.Add(Radio);
        }
    }

    /// <summary>
    /// A PPI line: --baud 9600, 19200 or 187500 (the S7-200's PPI rates, seed 002 Tables A-2 to A-4), always 8 data bits,
    /// even parity and one stop bit (ML801761 p. 228): --parity and --data-bits may only say so.
    /// </summary>
    public bool TryBindPpi(ParseResult parse, [NotNullWhen(true)] out SerialSettings? serial, [NotNullWhen(false)] out string? error) =>
        TryBindPpi(parse, null, out serial, out error);

    /// <summary>As above; <paramref name="fallbackPort"/> names the port when --device is absent (the demo line).</summary>
    public bool TryBindPpi(ParseResult parse, string? fallbackPort, [NotNullWhen(true)] out SerialSettings? serial, [NotNullWhen(false)] out string? error)
    {
        serial = null;
        var baud = parse.GetValue(Baud);
        if (!PpiRates.Contains(baud))
        {
            error = $"baud {baud} is not a PPI rate; PPI runs at {string.Join(", ", PpiRates)}";
            return false;
        }

        if ((parse.GetResult(Parity) is { Implicit: false } && parse.GetValue(Parity) != Core.Transport.Parity.Even)
            || (parse.GetResult(DataBits) is { Implicit: false } && parse.GetValue(DataBits) != 8))
        {
            error = "PPI characters are always 8 data bits, even parity, one stop bit: leave out --parity and --data-bits or give even and 8";
            return false;
        }

        if (!TryBind(parse, fallbackPort, baud: 9600, out var line, out error))
        {
            return false;
        }

        if (line.Kind == LinkKind.RadioModule)
        {
            error = "the radio modules carry the handler's Freeport frames; PPI needs the cable: leave out --radio";
            return false;
        }

        serial = line with { BaudRate = baud, Parity = Core.Transport.Parity.Even, DataBits = 8, Protocol = LinkProtocol.Ppi };
        return true;
    }

    /// <summary>The line settings; <paramref name="fallbackPort"/> names the port when --device is absent (the demo line).</summary>
    public bool TryBind(ParseResult parse, string? fallbackPort, [NotNullWhen(true)] out SerialSettings? serial, [NotNullWhen(false)] out string? error) =>
        TryBind(parse, fallbackPort, parse.GetValue(Baud), out serial, out error);

    private bool TryBind(ParseResult parse, string? fallbackPort, int baud, [NotNullWhen(true)] out SerialSettings? serial, [NotNullWhen(false)] out string? error)
    {
        serial = null;
        var device = parse.GetValue(Device);
        var port = string.IsNullOrWhiteSpace(device) ? fallbackPort : device.Trim();
        if (port is null)
        {
            error = _panelSide
                ? "give the serial port with --device (e.g. --device COM3 or --device /dev/ttyUSB0), or --demo for the simulated PLC"
                : "give the serial device to serve on with --device (e.g. --device /dev/pts/N, one end of a socat pair, or --device COM4)";
            return false;
        }

        if (!FreeportRates.Contains(baud))
        {
            error = $"baud {baud} is not a Freeport rate; use one of {string.Join(", ", FreeportRates)}";
            return false;
        }

        var dataBits = parse.GetValue(DataBits);
        if (dataBits is not (7 or 8))
        {
            error = $"{dataBits} data bits: S7-200 Freeport sends 7 or 8";
            return false;
        }

        serial = new SerialSettings
        {
            PortName = port,
            BaudRate = baud,
            Parity = parse.GetValue(Parity),
            DataBits = dataBits,
            Kind = _panelSide && parse.GetValue(Radio) ? LinkKind.RadioModule : LinkKind.Cable,
        };
        error = null;
        return true;
    }
}
