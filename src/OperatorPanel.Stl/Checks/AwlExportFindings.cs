using System.Collections.Immutable;

namespace OperatorPanel.Stl.Checks;

/// <summary>What <see cref="AwlExportCheck"/> found: refusals (Micro/WIN would not import the file) and warnings.</summary>
public sealed record AwlExportFindings(ImmutableArray<AwlDiagnostic> Refusals, ImmutableArray<AwlDiagnostic> Warnings);
