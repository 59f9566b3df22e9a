using System.Collections.Immutable;
using System.CommandLine;
using OperatorPanel.Core.Projects;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// generate's and simulate's words for Core's <see cref="CompactStop"/> rule. The generator refuses a compact handler
/// with STOP (STL031) in the project file's words; on the command line either setting may come from an option
/// (--compact, --allow-stop), so the message says where each came from and how to clear it there. A project's settings
/// alone keep the file's words, the same sentence <c>opanel project check</c> prints.
/// </summary>
internal static class CompactStopOptions
{
    /// <summary><paramref name="diagnostics"/> with STL031, if there, in the words of the options given.</summary>
    public static ImmutableArray<StlDiagnostic> Reword(
        ImmutableArray<StlDiagnostic> diagnostics, HandlerOptionSet set, ParseResult parse, HandlerOptions station, string who) =>
        [.. diagnostics.Select(d => d.Id == StlDiagnostics.CompactHandlerHasNoStop ? d with { Message = CompactStop.Describe(who, Words(set, parse, station)) } : d)];

    /// <summary>
    /// <paramref name="station"/>: the settings the project gave. --compact wins over the project's "compact", and
    /// --allow-stop over its "allowStop" (--allow-stop false takes STOP away; HandlerOptionSet.TryApply).
    /// </summary>
    private static CompactStopWords Words(HandlerOptionSet set, ParseResult parse, HandlerOptions station)
    {
        var compactOption = parse.GetResult(set.Compact) is { Implicit: false };
        var stopOption = parse.GetResult(set.AllowStop) is { Implicit: false } && parse.GetValue(set.AllowStop);
        if (!compactOption && !stopOption)
        {
            return CompactStopWords.File;
        }

        var (compact, compactOff) = compactOption
            ? ("--compact", station.Compact ? "give --compact false" : "leave out --compact")
            : ("\"compact\": true", "give --compact false (or set \"compact\": false)");
        var (stop, stopOff) = (station.AllowStop, stopOption) switch
        {
            (true, true) => ("\"allowStop\": true (--allow-stop too)", "give --allow-stop false"),
            (true, false) => ("\"allowStop\": true", "give --allow-stop false (or set \"allowStop\": false)"),
            _ => ("--allow-stop", "leave out --allow-stop"),
        };
        return new CompactStopWords(compact, stop, compactOff, stopOff);
    }
}
